// The system's linear and angular momentum in the inertial frame (body 0's
// parent), the angular part about the system's centre of mass; conserved
// when nothing acts from outside, as on a free-floating bus.
#pragma once

#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/model.hpp"

namespace unfurl::sim {

struct SystemMomentum {
  Vec3 linear = Vec3::Zero();
  Vec3 angular = Vec3::Zero();
  // The sums of the bodies' own magnitudes: the scale a drift is measured
  // against (the total is zero on a bus released at rest).
  double linear_scale = 0;
  double angular_scale = 0;
};

// From the poses, h: each body's own momentum (linear, angular about its
// origin) in its frame: M_i v_i, or a flexible body's frame part of M^ (v_i,
// eta'), and each body's centre of mass in its frame (a flexible body's as
// deformed: with its undeformed one the centre would wander as the body
// bends, and the angular momentum about it with it).
SystemMomentum system_momentum(const Model& model, const std::vector<Pose>& poses, const std::vector<Vec6>& h,
                               const std::vector<Vec3>& centres);

// The orientation a ball or free joint gives its child, from q and q': the
// quaternion (w, x, y, z, unit), the rotation vector (angle times axis, the
// angle in [0, pi]) and the angular rate in the child's frame.
struct JointOrientation {
  Eigen::Vector4d quaternion;
  Vec3 rotation_vector;
  Vec3 rate;
};
JointOrientation joint_orientation(const Model& model, int joint, const double* q, const double* dq);
// A free-floating bus's (joint 0's).
inline JointOrientation bus_motion(const Model& model, const double* q, const double* dq) {
  return joint_orientation(model, 0, q, dq);
}

// The angle of the rotation from attitude a to attitude b (unit quaternions).
double rotation_angle_between(const Eigen::Vector4d& a, const Eigen::Vector4d& b);

}  // namespace unfurl::sim
