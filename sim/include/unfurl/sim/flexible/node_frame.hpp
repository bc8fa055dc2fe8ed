// The frame a child of a flexible body hangs on (docs/FLEXIBLE.md): six
// massless virtual joints from the body's frame, three slides along its
// axes and three turns about x, y and z in turn, whose coordinates s =
// (point, 0) + L eta are driven by the node's shape L. Each virtual joint
// has a constant axis in its own frame, so (7) holds for it as for a hinge:
// dT/ds_k = -a_k^T Omega(v_k) mu_k.
#pragma once

#include <array>

#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim::flexible {

// A placement as the 6 x 6 matrix C of (1).
inline Mat6 velocity_matrix(const Placement& X) {
  Mat6 C = Mat6::Zero();
  C.topLeftCorner<3, 3>() = X.G;
  C.topRightCorner<3, 3>() = -X.G * skew(X.rho);
  C.bottomRightCorner<3, 3>() = X.G;
  return C;
}

// Composition: X_a then X_b (b placed in a's child frame).
inline Placement then(const Placement& a, const Placement& b) { return {b.G * a.G, a.rho + a.G.transpose() * b.rho}; }

using NodeRates = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxModes>;

class NodeFrame {
 public:
  // At elastic coordinates eta (the body's m of them).
  void set(const FlexibleNode& node, const double* eta);

  // The body frame to the node frame.
  const Placement& placement() const { return to_node_; }
  // The node frame's velocity per unit eta': A L (6 x m).
  const NodeRates& rates() const { return AL_; }
  // The node frame's acceleration beyond C_node a + A L eta'': the virtual
  // joints' velocity products v_k x (a_k s'_k), carried to the node frame.
  Vec6 velocity_product(const Vec6& v, const double* eta_dot) const;
  // Adds to g the dT/d eta of everything hung at the node: L^T (-a_k^T
  // Omega(v_k) mu_k)_k for the body frame's velocity v, the elastic rates
  // eta' and the momentum mu hung at the node (node frame).
  void add_kinetic_gradient(const Vec6& v, const double* eta_dot, const Vec6& mu, Eigen::Ref<Eigen::VectorXd> g) const;

 private:
  const FlexibleNode* node_ = nullptr;
  std::array<Placement, 6> X_;  // each virtual joint's, from the frame before
  Placement to_node_;
  Mat6 A_;  // the six axes carried to the node frame
  NodeRates AL_;
};

}  // namespace unfurl::sim::flexible
