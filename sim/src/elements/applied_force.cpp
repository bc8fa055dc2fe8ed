#include "unfurl/sim/elements/applied_force.hpp"

#include "unfurl/sim/elements/point_frame.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

Vec6 wrench_at_origin(const Vec3& force, const Vec3& torque, const Vec3& point) {
  Vec6 F;
  F.head<3>() = force;
  F.tail<3>() = torque + point.cross(force);
  return F;
}

// On a flexible body the load acts at the node frame its point rides on,
// and a body-frame load turns with it (a follower load on the material).
void AppliedForce::add_forces(const ElementState& s, ElementForces& out) const {
  if (in_base_frame) {
    const PointFrame at = point_frame(s, body, point);
    const Mat3& R = at.pose.rotation;
    add_frame_wrench(s, body, at.node, wrench_at_origin(R * force, R * torque, at.r), out);
    return;
  }
  const flexible::FlexibleBody* f = s.model.bodies[body].flexible.get();
  const int node = f ? f->node_of(point) : -1;
  add_frame_wrench(s, body, node, wrench_at_origin(force, torque, node < 0 ? point : Vec3(point - f->nodes[node].point)),
                   out);
}

std::vector<ElementParameter> AppliedForce::parameters(const Model& /*model*/) const {
  std::vector<ElementParameter> p;
  const char* axes[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    p.push_back({"force." + std::to_string(a), std::string("force ") + axes[a] + " [N]", force[a], 0.1, 0, 0,
                 "the applied force, in the body's frame (or the base's)"});
  for (int a = 0; a < 3; ++a)
    p.push_back({"torque." + std::to_string(a), std::string("torque ") + axes[a] + " [N m]", torque[a], 0.01, 0, 0,
                 "the applied torque, in the body's frame (or the base's)"});
  return p;
}

void AppliedForce::validate(const Scene& scene, const std::string& field) const {
  if (body < 0 || body >= scene.model.size()) throw SceneInvalid(field + ".body", "the base cannot carry this");
  node_of_point(scene, body, point, field + ".point");
  if (in_base_frame && scene.model.base_rotates())
    throw SceneInvalid(field + ".frame", "base-frame loads need a base that does not rotate");
}

std::shared_ptr<ForceElement> AppliedForce::scaled(double L, double M, const Model&) const {
  auto a = std::make_shared<AppliedForce>(*this);
  a->force *= M * L;
  a->torque *= M * L * L;
  a->point *= L;
  return a;
}

}  // namespace unfurl::sim
