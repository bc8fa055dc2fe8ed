// Joints of the tree: G_i(q), rho_i(q) and the motion axis A_i of (1).
//
// The child frame coincides in orientation with the parent frame at q = 0;
// the joint turns (or slides) it about (along) a unit axis fixed in both.
// All supported joints are scleronomic (v*_i = 0) and have a constant A_i,
// so dA_i/dt of (7) vanishes.
#pragma once

#include <string>

#include "unfurl/sim/spatial.hpp"

namespace unfurl {

enum class JointType { revolute, prismatic, fixed };

const char* joint_type_name(JointType type);

struct Joint {
  std::string name;
  JointType type = JointType::revolute;
  Vec3 axis = Vec3::UnitX();        // unit vector, parent frame
  Vec3 parent_point = Vec3::Zero(); // r^k: the hinge point in the parent frame
  Vec3 child_point = Vec3::Zero();  // r^i: the same point in the child frame

  // Number of coordinates n_i (0 or 1).
  int dof() const { return type == JointType::fixed ? 0 : 1; }

  // G_i(q) and rho_i(q) = r^k - G^T r^i (+ axis q for a slider).
  Placement placement(double q) const;

  // A_i = (G drho/dq ; a) of (1); zero for a fixed joint.
  Vec6 motion_axis() const;
};

}  // namespace unfurl
