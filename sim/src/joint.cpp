#include "unfurl/sim/joint.hpp"

namespace unfurl {

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::revolute: return "revolute";
    case JointType::prismatic: return "prismatic";
    case JointType::fixed: return "fixed";
  }
  return "?";
}

Placement Joint::placement(double q) const {
  Placement P;
  switch (type) {
    case JointType::revolute:
      // The child turns by q about the axis: G = R(axis, q)^T.
      P.G = Eigen::AngleAxisd(q, axis).toRotationMatrix().transpose();
      P.rho = parent_point - P.G.transpose() * child_point;
      break;
    case JointType::prismatic:
      P.rho = parent_point - child_point + axis * q;
      break;
    case JointType::fixed:
      P.rho = parent_point - child_point;
      break;
  }
  return P;
}

Vec6 Joint::motion_axis() const {
  Vec6 A = Vec6::Zero();
  switch (type) {
    case JointType::revolute:
      // G R~ R^T = axis~, so a^v = -axis x r^i and a^w = axis.
      A.head<3>() = child_point.cross(axis);
      A.tail<3>() = axis;
      break;
    case JointType::prismatic:
      A.head<3>() = axis;
      break;
    case JointType::fixed:
      break;
  }
  return A;
}

}  // namespace unfurl
