// The tree of bodies (the method's secondary graph): bodies 1..N (stored
// 0..N-1), joint i between body i and its parent k_i, body 0 (the base)
// with a given motion.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/coordinates.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/joint.hpp"
#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

struct Body {
  std::string name;
  double mass = 0;
  Vec3 com = Vec3::Zero();            // centre of mass, body frame
  Mat3 inertia_com = Mat3::Zero();    // about the centre of mass, body axes
  // A flexible body's elastic model (docs/FLEXIBLE.md); null for a rigid
  // one. Its mass and inertia are then the invariants', not the fields
  // above.
  std::shared_ptr<const flexible::FlexibleBody> flexible;

  // J_i of (6): the inertia about the body origin (parallel axes).
  Mat3 inertia_origin() const;
  // M_i of (6).
  Mat6 spatial_mass() const { return spatial_inertia(mass, com, inertia_origin()); }
};

inline constexpr int kBase = -1;  // index of body 0 in parent arrays

struct Model {
  std::string base_name = "base";
  std::vector<Body> bodies;
  std::vector<Joint> joints;  // joint i carries body i
  std::vector<int> parent;    // k_i, kBase for body 0
  // The node of the parent's flexible body that joint i hangs on (an index
  // into FlexibleBody::nodes; its placement is then from the node's frame,
  // with the node's point taken off rho), -1 on a rigid parent. Empty: all
  // -1.
  std::vector<int> parent_node;
  // The base's velocity (v, w) in its own frame, constant: a steady drift
  // or spin of body 0. Zero for a fixed base.
  Vec6 base_velocity = Vec6::Zero();

  // Derived by finalize().
  std::vector<std::vector<int>> children;  // U_i
  // Where each joint's coordinates sit: its m_i positions from
  // first_position[i] in q, its n_i velocity coordinates (and momenta) from
  // first_velocity[i] in the rates and p; invalid for a fixed joint. The
  // one-coordinate joints come first in both, in body order, so that the
  // trajectory's columns keep them together; nothing else relies on it.
  std::vector<PositionIndex> first_position;
  std::vector<VelocityIndex> first_velocity;
  std::vector<int> joint_of_position;  // per entry of q; -1 for an elastic coordinate
  std::vector<int> joint_of_velocity;  // per entry of the rates; -1 for an elastic coordinate
  // A flexible body's m elastic coordinates, after every joint's: from
  // first_elastic_position[i] in q and first_elastic_velocity[i] in the
  // rates and p (the rates are eta' themselves); -1 for a rigid body.
  std::vector<int> first_elastic_position, first_elastic_velocity;
  std::vector<int> body_of_elastic_velocity;  // per entry of the rates, -1 for a joint's
  int nq = 0;  // positions
  int nv = 0;  // velocity coordinates

  int size() const { return static_cast<int>(bodies.size()); }
  // Names of q's entry c and of the rates' entry c in outputs: the joint's
  // name for a one-coordinate joint, "joint.qw" or "joint.wx" for the
  // entries of a ball, planar or free joint, "body.eta3" for a flexible
  // body's third elastic coordinate.
  std::string position_name(int c) const;
  std::string velocity_name(int c) const;
  // The SI units of q's entry c, of the rates' entry c and of the momentum
  // conjugate to it: "rad", "rad/s", "N m s" on a hinge; "m", "m/s", "N s"
  // on a slider; "" for a quaternion's entries.
  std::string position_unit(int c) const;
  std::string velocity_unit(int c) const;
  std::string momentum_unit(int c) const;
  // The single coordinate of a one-coordinate joint j, in each space.
  PositionIndex position_of(int j) const { return first_position[j]; }
  VelocityIndex velocity_of(int j) const { return first_velocity[j]; }
  // Builds U_i and the coordinate map; throws std::invalid_argument when the
  // numbering is not regular (a parent after its child).
  void finalize();
  // The index of the body, or of the joint, called `name` (kBase for the
  // base's name), or nothing.
  std::optional<int> find_body(const std::string& name) const;
  std::optional<int> find_joint(const std::string& name) const;
  bool base_rotates() const { return !base_velocity.tail<3>().isZero(0); }
  // Whether some joint has several coordinates (then nq may differ from nv).
  bool has_multi_dof_joints() const { return scalar_coordinates != nv; }
  int scalar_coordinates = 0;  // how many one-coordinate joints (the first of q and of the rates)
  // Body 0 on a free joint: a free-floating spacecraft bus.
  bool free_floating() const { return !joints.empty() && joints[0].type == JointType::free; }
  int elastic_coordinates = 0;  // all flexible bodies' together
  bool has_flexible_bodies() const { return elastic_coordinates > 0; }
  bool flexible(int i) const { return bodies[i].flexible != nullptr; }
  int node_of(int j) const { return parent_node.empty() ? -1 : parent_node[j]; }
};

}  // namespace unfurl::sim
