// The reduced model of a flexible body on its floating frame, by Craig and
// Bampton's component modes (AIAA J. 6(7), 1968): the structure's modes
// with the frame's attachment and the other attachment points held (the
// fixed-interface normal modes, as many as asked), and the static shape of
// a unit motion of each other attachment degree of freedom (the constraint
// modes); then orthonormalized, by solving the eigenproblem of the reduced
// matrices with the frame held, as Adams does with a Nastran MNF, so that
// each elastic coordinate has unit modal mass, stiffness omega_k^2 and a
// damping ratio of its own.
//
// Why Craig-Bampton and not free-interface modes: a panel's loads enter at
// its hinges and latches, points where free modes converge slowly and need
// a residual-flexibility correction; the constraint modes hold the static
// deformation under a load at an attachment point exactly. Holding the
// frame's attachment makes the frame the inboard hinge's own (a tangent
// frame), so a joint attaches the body where the body's frame is.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "unfurl/sim/flexible/structure.hpp"

namespace unfurl::sim::flexible {

struct ModalReduction {
  // Held to define the frame: they must leave no rigid motion free, and
  // should hold no more than the rigid motions (more ties the frame's
  // attachment rigid, as an RBE2 would).
  std::vector<int> frame_dofs;
  std::vector<int> interface_dofs;  // the other attachment points', one constraint mode each
  int normal_modes = 0;             // fixed-interface modes kept
};

struct ModalBody {
  // Over the structure's degrees of freedom, one column per elastic
  // coordinate (normal_modes + interface_dofs.size() of them): Phi^T M Phi
  // = I, Phi^T K Phi = diag((2 pi f)^2).
  Eigen::MatrixXd shape;
  Eigen::VectorXd frequency_hz;  // ascending, the frame held
  // The inertia coupling of the frame's motion (linear part first) with
  // the elastic rates at zero deformation, R^T M Phi: 6 x shape.cols().
  Eigen::MatrixXd coupling;

  int coordinates() const { return static_cast<int>(shape.cols()); }
  // A node's small translation and rotation per unit elastic coordinate:
  // 6 x coordinates().
  Eigen::MatrixXd node_shape(const Structure& structure, int node) const;
};

// Throws std::invalid_argument when the frame's degrees of freedom leave a
// rigid motion free, or fewer normal modes exist than asked.
ModalBody reduce(const Structure& structure, const ModalReduction& reduction);

}  // namespace unfurl::sim::flexible
