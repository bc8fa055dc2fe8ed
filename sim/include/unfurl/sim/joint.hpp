// Joints of the tree: G_i(q), rho_i(q) and the motion axes A_i of (1).
//
// The child frame coincides in orientation with the parent frame at q = 0
// (the identity quaternion for a ball or free joint). Every joint is
// scleronomic (v*_i = 0). A revolute or prismatic joint turns or slides
// about a fixed axis; a spherical, planar or free joint takes as velocity
// coordinates the child's relative velocity in the child frame (angular
// rate, and the joint point's linear velocity), quasi-velocities whose q'
// is not their own rate but follows from them (position_rates). For all of
// these A_i is constant in the child frame, so dA_i/dt of (7) vanishes. A
// universal joint turns by q1 about `axis` (parent frame), then by q2
// about `axis2` (carried by the first turn, as by a cross): its rates are
// q', but its first column turns with q2 in the child frame, so it has
// the dA_i/dt of (7) (motion_axes_rate).
//
// A compliant revolute joint (`compliant`) is a hinge whose pin gives: its
// child turns by q about the axis as ever, but the pin also moves in its
// bearing by u1, u2 across the axis (along e1 = the axis' unitOrthogonal,
// e2 = axis x e1), ua along it, and tilts by r1 about e1, then r2 about
// e2 as the first tilt carries it: R = R(e1, r1) R(e2, r2) R(axis, q), rho
// = r^k + u1 e1 + u2 e2 + ua axis - R r^i. Its coordinates are (q, u1, u2,
// ua, r1, r2), rates their q', and A_i turns with them (motion_axes_rate).
// The pin's stiffness and damping act on the five (joint_compliance.hpp),
// and the joint's reaction is what they carry.
//
// Coordinates: n_i velocity coordinates (dof) and m_i position coordinates
// (positions): revolute and prismatic 1/1 (a compliant revolute 6/6), fixed 0/0, universal 2/2,
// spherical 3/4 (a unit quaternion w, x, y, z), planar 3/3 (x1, x2 along
// two in-plane axes, angle about the normal), free 6/7 (the joint point's
// displacement x, y, z in the parent frame, then a quaternion).
#pragma once

#include <optional>
#include <string>

#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

enum class JointType { revolute, prismatic, fixed, spherical, planar, free, universal };

const char* joint_type_name(JointType type);
// The type a scene file names ("revolute", ...), or nullopt.
std::optional<JointType> parse_joint_type(const std::string& name);

struct Joint {
  std::string name;
  JointType type = JointType::revolute;
  Vec3 axis = Vec3::UnitX();        // unit vector, parent frame (a planar joint's normal)
  Vec3 axis2 = Vec3::UnitY();       // a universal joint's second axis (child frame, = parent frame at q = 0)
  Vec3 parent_point = Vec3::Zero(); // r^k: the hinge point in the parent frame
  Vec3 child_point = Vec3::Zero();  // r^i: the same point in the child frame
  bool compliant = false;           // a revolute joint whose pin gives (above)
  // Its motion is prescribed (a JointDriver says how; validate() sets this
  // from the drivers): the sweep takes its rate, not its momentum.
  bool driven = false;

  // n_i: velocity coordinates (and momenta).
  int dof() const;
  // m_i: position coordinates (4 for a quaternion).
  int positions() const;
  // Whether the joint's coordinates are angles or lengths that a spring,
  // a latch or friction can act on (one coordinate, q' its rate).
  bool is_scalar() const { return dof() == 1; }
  // Whether it carries a reaction: a free joint (a free-floating bus) joins
  // its body to nothing, so its wrench is zero and is not reported.
  bool has_reaction() const { return type != JointType::free; }
  // Whether springs, dampers, friction and latches can act on it: a
  // revolute or prismatic joint, on its first coordinate (a compliant
  // hinge's angle).
  bool has_free_coordinate() const { return type == JointType::revolute || type == JointType::prismatic; }
  // Whether an orientation is a quaternion in q (spherical and free).
  bool has_quaternion() const { return type == JointType::spherical || type == JointType::free; }
  // Offset of the quaternion in the joint's positions.
  int quaternion_offset() const { return type == JointType::free ? 3 : 0; }

  // G_i and rho_i = r^k + (displacement) - G^T r^i for the joint's m_i
  // positions q (a quaternion is normalized here, so its norm never enters
  // the dynamics); q is not read for a fixed joint.
  Placement placement(const double* q) const;
  Placement placement(double q) const { return placement(&q); }

  // A_i = (G drho/dq ; a) of (1): 6 x n_i, in the leading columns of a 6 x 6
  // (the rest zero), at positions q (read only by a universal joint).
  Mat6 motion_axes(const double* q = nullptr) const;
  // The single column of a one-coordinate joint.
  Vec6 motion_axis() const { return motion_axes().col(0); }
  // Whether A_i depends on q (a universal joint).
  bool has_varying_axes() const { return type == JointType::universal || compliant; }
  // A compliant joint's axes across its own: e1, e2.
  Vec3 cross_axis_1() const { return axis.unitOrthogonal(); }
  Vec3 cross_axis_2() const { return axis.cross(cross_axis_1()); }
  // dA_i/dt at positions q and rates w (zero but for a universal joint).
  Mat6 motion_axes_rate(const double* q, const double* w) const;

  // q' of the positions from the velocity coordinates w: the same numbers
  // for revolute and prismatic joints; x' = G^T u and a quaternion's
  // q' = q (x) (0, w) / 2 otherwise.
  void position_rates(const double* q, const double* w, double* dq) const;

  // The inverse: the rates w from q and q'.
  void rates(const double* q, const double* dq, double* w) const;

  // The positions of the reference configuration (identity quaternion).
  void neutral_positions(double* q) const;

  // The planar joint's in-plane axes (e1, e2, axis right-handed).
  Vec3 plane_axis_1() const { return axis.unitOrthogonal(); }
  Vec3 plane_axis_2() const { return axis.cross(plane_axis_1()); }
};

// The rotation of a quaternion (w, x, y, z), normalized, child to parent.
Mat3 quaternion_rotation(const double* q);

}  // namespace unfurl::sim
