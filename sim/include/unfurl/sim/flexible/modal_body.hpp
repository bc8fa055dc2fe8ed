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
  int normal_modes = 0;              // fixed-interface modes kept
  // Sets of nodes tied rigid to one another (an RBE2 spider: a hinge line
  // along a panel's edge), each held in the fixed-interface modes and
  // given one constraint mode per rigid motion the structure models (a
  // plate's three out of its plane), so that a line of nodes costs three
  // coordinates where the nodes' own degrees of freedom would cost dozens.
  std::vector<std::vector<int>> tied_nodes;
  // Where positive, instead of normal_modes: every fixed-interface mode up
  // to this frequency (Hz).
  double normal_modes_up_to_hz = 0;
};

struct ModalBody {
  // Over the structure's degrees of freedom, one column per elastic
  // coordinate (the normal modes, one per interface degree of freedom and
  // one per tied set's modelled rigid motion): Phi^T M Phi = I, Phi^T K
  // Phi = diag((2 pi f)^2).
  Eigen::MatrixXd shape;
  Eigen::VectorXd frequency_hz;  // ascending, the frame held
  // The inertia coupling of the frame's motion (linear part first) with
  // the elastic rates at zero deformation, R^T M Phi: 6 x shape.cols().
  Eigen::MatrixXd coupling;

  int coordinates() const { return static_cast<int>(shape.cols()); }
  // A node's small translation and rotation per unit elastic coordinate:
  // 6 x coordinates().
  Eigen::MatrixXd node_shape(const Structure& structure, int node) const;
  // The small translation (at `point`, the structure's frame) and rotation
  // per unit elastic coordinate of a tied set of nodes, which moves
  // rigidly: 6 x coordinates().
  Eigen::MatrixXd tie_shape(const Structure& structure, const std::vector<int>& tied, const Eigen::Vector3d& point) const;
};

// Throws std::invalid_argument when the frame's degrees of freedom leave a
// rigid motion free, or fewer normal modes exist than asked.
ModalBody reduce(const Structure& structure, const ModalReduction& reduction);

}  // namespace unfurl::sim::flexible
