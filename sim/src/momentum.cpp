#include "unfurl/sim/momentum.hpp"

#include <algorithm>
#include <cmath>

namespace unfurl::sim {

SystemMomentum system_momentum(const Model& model, const std::vector<Pose>& poses, const std::vector<Vec6>& h_body,
                               const std::vector<Vec3>& centres) {
  SystemMomentum out;
  double mass = 0;
  Vec3 first_moment = Vec3::Zero();
  for (int i = 0; i < model.size(); ++i) {
    mass += model.bodies[i].mass;
    first_moment += model.bodies[i].mass * poses[i].to_base(centres[i]);
  }
  const Vec3 centre = first_moment / mass;
  for (int i = 0; i < model.size(); ++i) {
    // (linear momentum, angular momentum about the body origin) in the body
    // frame; moved to the inertial axes and the centre.
    const Vec6& h = h_body[i];
    const Mat3 Gt = poses[i].rotation.transpose();
    const Vec3 P = Gt * h.head<3>();
    const Vec3 L = Gt * h.tail<3>() + (poses[i].position - centre).cross(P);
    out.linear += P;
    out.angular += L;
    out.linear_scale += P.norm();
    out.angular_scale += L.norm();
  }
  return out;
}

JointOrientation joint_orientation(const Model& model, int joint, const double* q, const double* dq) {
  const Joint& j = model.joints[joint];
  const int c = model.first_position[joint].value, at = c + j.quaternion_offset();
  Vec6 w;
  j.rates(q + c, dq + c, w.data());
  Eigen::Quaterniond attitude(q[at], q[at + 1], q[at + 2], q[at + 3]);
  attitude.normalize();
  if (attitude.w() < 0) attitude.coeffs() *= -1;  // the shorter way round
  const Eigen::AngleAxisd turn(attitude);
  return {Eigen::Vector4d(attitude.w(), attitude.x(), attitude.y(), attitude.z()), turn.angle() * turn.axis(),
          w.segment<3>(j.dof() - 3)};
}

double rotation_angle_between(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return 2 * std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}

}  // namespace unfurl::sim
