#include "unfurl/sim/forces.hpp"

namespace unfurl {

namespace {
Vec6 wrench_at_origin(const Vec3& force, const Vec3& torque, const Vec3& point) {
  Vec6 F;
  F.head<3>() = force;
  F.tail<3>() = torque + point.cross(force);
  return F;
}
}  // namespace

bool loads_need_poses(const Model& model, const std::vector<BodyLoad>& loads) {
  if (!model.gravity.isZero(0)) return true;
  for (const BodyLoad& load : loads)
    if (load.in_base_frame) return true;
  return false;
}

void add_body_loads(const Model& model, const std::vector<BodyLoad>& loads,
                    const std::vector<Pose>& poses, std::vector<Vec6>& F) {
  for (const BodyLoad& load : loads) {
    if (load.in_base_frame) {
      const Mat3& R = poses[load.body].rotation;
      F[load.body] += wrench_at_origin(R * load.force, R * load.torque, load.point);
    } else {
      F[load.body] += wrench_at_origin(load.force, load.torque, load.point);
    }
  }
  if (model.gravity.isZero(0)) return;
  for (int i = 0; i < model.size(); ++i) {
    const Body& b = model.bodies[i];
    F[i] += wrench_at_origin(poses[i].rotation * (b.mass * model.gravity), Vec3::Zero(), b.com);
  }
}

double gravity_energy(const Model& model, const std::vector<Pose>& poses) {
  if (model.gravity.isZero(0)) return 0.0;
  double V = 0;
  for (int i = 0; i < model.size(); ++i) {
    const Body& b = model.bodies[i];
    V -= b.mass * model.gravity.dot(poses[i].to_base(b.com));
  }
  return V;
}

}  // namespace unfurl
