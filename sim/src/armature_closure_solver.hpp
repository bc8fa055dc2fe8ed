// Solves with R_B = eps T A B^-1 (eps T A)^T + diag(delta), where B =
// Mtilde + diag(armature) is the tree's part of the implicit integrators'
// Newton matrix (the joints' gamma D + gamma^2 K entering as armature,
// newton_preconditioner.hpp): the loops' mobility of the mechanism as a
// Newton iteration sees it. The sparse closure system (closure_solver.hpp)
// with each joint's armature on the relative velocity of its two bodies,
// so it keeps the primary graph's pattern and its O(N) factorization.
// Its solve() refines exactly once, whatever `refine` says: a fixed linear
// map, as a Krylov method needs of its preconditioner.
#pragma once

#include <memory>
#include <vector>

#include "unfurl/sim/closure_solver.hpp"

namespace unfurl::sim {

class ArmatureClosureSolver : public ClosureSolver {
 public:
  // armature: one value per velocity coordinate (joint and elastic), >= 0.
  virtual bool factorize(const Sweep& sweep, const double* delta, const double* armature) = 0;
  using ClosureSolver::factorize;
};

std::unique_ptr<ArmatureClosureSolver> make_armature_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                                    const std::vector<LoopComponent>& components);

}  // namespace unfurl::sim
