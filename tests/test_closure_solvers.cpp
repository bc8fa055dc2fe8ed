// The closure solvers (solves with R = W + delta I) against the dense
// formulation's W: the dense and sparse ones, away from and at the deployed
// branch point where W loses rank; the W a factorization formed, reused.
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

TEST(ClosureSolver, SparseSolvesThroughFlexiblePanels) {
  // The loops close through the plates' nodes: the sparse system carries
  // each plate's extended velocity, its M^(eta) and its nodes' N_a, and
  // solves as the dense solver's W from the sweep's passes does, here with
  // the plates bent.
  const sim::Scene scene = test::scene_file("pantograph_flexible");
  const sim::Model& model = scene.model;
  VectorXd q = 0.7 * Eigen::Map<const VectorXd>(scene.q0.data(), model.nq);
  int bent = 0;
  for (int i = 0; i < model.size(); ++i) {
    if (!model.flexible(i)) continue;
    for (int k = 0; k < model.bodies[i].flexible->modes(); ++k, ++bent)
      q[model.first_elastic_position[i] + k] = 2e-3 * (k + 1) * (bent % 2 ? -1 : 1);
  }
  ASSERT_GT(bent, 0);
  sim::Dynamics dynamics(scene);
  const std::vector<sim::LoopComponent>& components = dynamics.regulator()->components();
  const int m = static_cast<int>(components.size());
  sim::Sweep sweep(model);
  sweep.set_configuration(q.data());
  const VectorXd deltas = VectorXd::Constant(m, 1e-6);
  Eigen::MatrixXd B(m, 2), X[2];
  B.col(0) = VectorXd::LinSpaced(m, -1, 1);
  B.col(1) = VectorXd::LinSpaced(m, 2, -0.5);
  const sim::ClosureSolverKind kinds[2] = {sim::ClosureSolverKind::dense, sim::ClosureSolverKind::sparse};
  for (int s = 0; s < 2; ++s) {
    const auto solver = sim::make_closure_solver(kinds[s], model, scene.loops, components);
    ASSERT_TRUE(solver->factorize(sweep, deltas.data()));
    X[s].resize(m, 2);
    solver->solve(B.data(), X[s].data(), 2);
  }
  for (int c = 0; c < 2; ++c) EXPECT_LT(test::relative_error(X[1].col(c), X[0].col(c)), 1e-9) << "column " << c;
}

TEST(ClosureSolver, TheWOfAFactorizationServesOnlyItsOwnConfiguration) {
  // The loads' rank analysis reads W from the regulator's dense
  // factorization where the configuration key is the one factored for, and
  // forms W anew at any other.
  const sim::Scene scene = test::scene_file("pantograph");
  sim::Dynamics dynamics(scene);
  sim::Regulator& regulator = *dynamics.regulator();
  sim::Sweep sweep(scene.model);
  const VectorXd q0 = Eigen::Map<const VectorXd>(scene.q0.data(), scene.model.nq);
  const VectorXd q1 = 0.7 * q0, q2 = 0.5 * q0;
  const long key1 = 1000001, key2 = 1000002;  // beyond any the dynamics used
  sweep.set_configuration(q1.data());
  ASSERT_TRUE(regulator.factorize(sweep, key1));
  const Eigen::MatrixXd formed_at_q1 = regulator.mobility(sweep);
  EXPECT_EQ(Eigen::MatrixXd(regulator.mobility(sweep, key1)), formed_at_q1);
  sweep.set_configuration(q2.data());
  const Eigen::MatrixXd at_q2 = regulator.mobility(sweep, key2);
  EXPECT_EQ(at_q2, Eigen::MatrixXd(regulator.mobility(sweep)));
  EXPECT_GT((at_q2 - formed_at_q1).norm(), 1e-3 * formed_at_q1.norm());
}

}  // namespace
}  // namespace unfurl
