// The closure solvers (solves with R = W + delta I) against the dense
// formulation's W: the dense and sparse ones, away from and at the deployed
// branch point where W loses rank.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "closure_check.hpp"
#include "support.hpp"
#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/dynamics.hpp"

namespace unfurl {
namespace {

using Eigen::VectorXd;
using test::expect_closure_solve_matches_dense;

TEST(ClosureSolver, DenseAndSparseSolveWithWPlusDelta) {
  const sim::Scene scene = test::scene_file("pantograph");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.7 * scene.q0[k];
  for (const auto kind : {sim::ClosureSolverKind::dense, sim::ClosureSolverKind::sparse})
    expect_closure_solve_matches_dense(scene, kind, q, 1e-5);
}

TEST(ClosureSolver, DenseAndSparseSolveOnAFreeFloatingBus) {
  // The free joint's 6 coordinates in the passes and the sparse system (a
  // joint with no constrained direction).
  const sim::Scene scene = test::scene_file("pantograph_free");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.7 * scene.q0[k];
  q.segment<3>(scene.model.first_position[0].value) << 0.1, -0.2, 0.3;
  q.segment<4>(scene.model.first_position[0].value + 3) << 0.9, 0.1, -0.3, 0.2;
  for (const auto kind : {sim::ClosureSolverKind::dense, sim::ClosureSolverKind::sparse})
    expect_closure_solve_matches_dense(scene, kind, q, 1e-5);
}

TEST(ClosureSolver, SparseHoldsAtTheDeployedBranchPoint) {
  // At q = 0 W loses rank: R = W + delta I is what keeps the solve defined.
  const sim::Scene scene = test::scene_file("pantograph");
  const VectorXd q = VectorXd::Zero(scene.model.nq);
  for (const double delta : {1e-3, 1e-5, 1e-7})
    expect_closure_solve_matches_dense(scene, sim::ClosureSolverKind::sparse, q, delta);
}

}  // namespace
}  // namespace unfurl
