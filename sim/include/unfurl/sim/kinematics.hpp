// Body poses from joint coordinates: r_i = r_{k_i} + G_0^{k_i T} rho_i and
// G_0^i = G_i G_0^{k_i} (section 1, with the paper's typo mended: rho_i is
// in the parent's frame).
#pragma once

#include <vector>

#include "unfurl/sim/model.hpp"

namespace unfurl::sim {

struct Pose {
  Vec3 position = Vec3::Zero();     // body origin, base frame
  Mat3 rotation = Mat3::Identity(); // G_0^i: base frame to body frame
  // A point given in the body frame, in the base frame.
  Vec3 to_base(const Vec3& x) const { return position + rotation.transpose() * x; }
  // The pose of a child placed by its joint: r_i = r_k + G_0^{k T} rho_i,
  // G_0^i = G_i G_0^k.
  Pose child(const Placement& X) const { return {to_base(X.rho), X.G * rotation}; }
};

// Joint i's placement of body i from its parent's frame at q: the joint's
// own, or on a flexible parent the node frame's (flexible/node_frame.hpp)
// then the joint's from the node.
Placement placement_in_parent(const Model& model, int i, const double* q);

// Poses of bodies 1..N in the frame of body 0 for coordinates q.
void body_poses(const Model& model, const double* q, std::vector<Pose>& poses);

// q' (nq) from the rates w (nv) at q, joint by joint (Joint::position_rates;
// the one-coordinate joints' entries are copied).
void position_rates(const Model& model, const double* q, const double* w, double* dq);
// The inverse: the rates w from q and q' (Joint::rates).
void rates_from_position_rates(const Model& model, const double* q, const double* dq, double* w);

}  // namespace unfurl::sim
