// The Krylov solver's Newton preconditioner with the loops in it: the
// closure system with the joints' armature (ArmatureClosureSolver) against
// the sweep's own passes, and the preconditioned Newton matrix P^-1 (I -
// gamma df/dy), formed column by column from Jacobian products, against
// the identity.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "armature_closure_solver.hpp"
#include "dense_formulation.hpp"
#include "newton_preconditioner.hpp"
#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// R_B = J B^-1 J^T + diag(delta) two ways: the dense solver's W from the
// sweep's passes with the armature in the articulated inertias, and the
// sparse system with it on each joint's relative velocity.
void expect_armature_solve_matches_the_passes(const sim::Scene& scene, const VectorXd& q) {
  const sim::Model& model = scene.model;
  sim::Dynamics dynamics(scene);
  const std::vector<sim::LoopComponent>& components = dynamics.regulator()->components();
  const int m = static_cast<int>(components.size());
  VectorXd armature(model.nv);
  for (int c = 0; c < model.nv; ++c) armature[c] = 0.05 * (1 + c % 3);  // kg m^2 (or kg m^2 per modal unit)
  sim::Sweep sweep(model);
  sweep.set_configuration(q.data(), armature.data());
  const VectorXd deltas = VectorXd::LinSpaced(m, 0.5, 1);  // 1 / (kg m^2), of W's own size
  MatrixXd B(m, 2), dense(m, 2), sparse(m, 2);
  B.col(0) = VectorXd::LinSpaced(m, -1, 1);
  B.col(1) = VectorXd::LinSpaced(m, 2, -0.5);
  const auto passes = sim::make_dense_closure_solver(model, scene.loops, components);
  ASSERT_TRUE(passes->factorize(sweep, deltas.data()));
  passes->solve(B.data(), dense.data(), 2);
  const auto closure = sim::make_armature_closure_solver(model, scene.loops, components);
  ASSERT_TRUE(closure->factorize(sweep, deltas.data(), armature.data()));
  closure->solve(B.data(), sparse.data(), 2);
  // Its one refinement pass at eps 1e-12 leaves 4e-9 to 8e-7 of the
  // solution (the same with no armature at all); a wrong armature moves it
  // by the armature's share of the inertia.
  sweep.set_configuration(q.data());
  const auto plain = sim::make_dense_closure_solver(model, scene.loops, components);
  ASSERT_TRUE(plain->factorize(sweep, deltas.data()));
  MatrixXd without(m, 2);
  plain->solve(B.data(), without.data(), 2);
  for (int c = 0; c < 2; ++c) {
    EXPECT_LT(test::relative_error(sparse.col(c), dense.col(c)), 1e-5) << "column " << c;
    EXPECT_GT(test::relative_error(without.col(c), dense.col(c)), 1e-2) << "column " << c;
  }
}

TEST(ArmatureClosureSolver, SolvesAsTheSweepWithArmature) {
  const sim::Scene scene = test::scene_file("pantograph");
  expect_armature_solve_matches_the_passes(scene, 0.7 * Eigen::Map<const VectorXd>(scene.q0.data(), scene.model.nq));
}

TEST(ArmatureClosureSolver, SolvesAsTheSweepWithArmatureOnAFreeBus) {
  // The free joint's six rates: H = P^T E P over its whole relative velocity.
  const sim::Scene scene = test::scene_file("pantograph_free");
  VectorXd q = 0.7 * Eigen::Map<const VectorXd>(scene.q0.data(), scene.model.nq);
  q.segment<3>(scene.model.first_position[0].value) << 0.1, -0.2, 0.3;
  q.segment<4>(scene.model.first_position[0].value + 3) << 0.9, 0.1, -0.3, 0.2;
  q.segment<4>(scene.model.first_position[0].value + 3).normalize();
  expect_armature_solve_matches_the_passes(scene, q);
}

TEST(ArmatureClosureSolver, SolvesAsTheSweepWithArmatureThroughBentPlates) {
  // Children on the plates' nodes (C N_a) and armature on elastic coordinates.
  const sim::Scene scene = test::scene_file("pantograph_flexible");
  const sim::Model& model = scene.model;
  VectorXd q = 0.7 * Eigen::Map<const VectorXd>(scene.q0.data(), model.nq);
  for (int i = 0; i < model.size(); ++i)
    if (model.flexible(i))
      for (int k = 0; k < model.bodies[i].flexible->modes(); ++k)
        q[model.first_elastic_position[i] + k] = 2e-3 * (k + 1) * (i % 2 ? -1 : 1);
  expect_armature_solve_matches_the_passes(scene, q);
}

// The largest |lambda - 1| over the eigenvalues of P^-1 (I - gamma df/dy)
// at the state y (with the dynamics' latches as they are engaged).
double preconditioned_spread(sim::Dynamics& dynamics, const std::vector<double>& y, double gamma) {
  const int n = dynamics.size();
  std::vector<double> f(n), e(n, 0.0), column(n);
  EXPECT_TRUE(dynamics.rhs(0, y.data(), f.data()));
  MatrixXd N(n, n), P_inverse_N(n, n);
  for (int j = 0; j < n; ++j) {
    e[j] = 1;
    EXPECT_TRUE(dynamics.jacobian_times(0, y.data(), e.data(), column.data()));
    N.col(j) = -gamma * Eigen::Map<const VectorXd>(column.data(), n);
    N(j, j) += 1;
    e[j] = 0;
  }
  dynamics.preconditioner().setup(y.data(), f.data(), gamma);
  for (int j = 0; j < n; ++j) {
    dynamics.preconditioner().solve(N.col(j).data(), column.data());
    P_inverse_N.col(j) = Eigen::Map<const VectorXd>(column.data(), n);
  }
  const Eigen::VectorXcd lambda = P_inverse_N.eigenvalues();
  return (lambda.array() - 1.0).abs().maxCoeff();
}

// The same at the scene's initial state.
double preconditioned_spread(const sim::Scene& scene, double gamma) {
  sim::Dynamics dynamics(scene);
  return preconditioned_spread(dynamics, dynamics.initial_state(), gamma);
}

TEST(NewtonPreconditioner, CarriesTheLoopsOfALargeArray) {
  // The generated 20-stage array (60 loop components, 184 states) at its
  // start, v_max 8,791 rad/s: gamma from BDF's shortest steps (one pole
  // pair merged, h v_max < 1) to its longest before the latch-up (about
  // 0.06 s). With the loops left to GMRES 60 eigenvalues lay at 1e2 to 1e7.
  const sim::Scene scene = studies::generate_pantograph(20).scene;
  for (const double gamma : {1e-5, 1e-3, 1e-2, 4e-2})
    EXPECT_LT(preconditioned_spread(scene, gamma), 0.05) << "gamma " << gamma;
}

TEST(NewtonPreconditioner, CarriesTheLoopsOnAFreeBus) {
  // The bus's free joint: its rates in B and the sparse system alike (its
  // quaternion's share of J rq is left to GMRES).
  const sim::Scene scene = test::scene_file("pantograph_free");
  for (const double gamma : {1e-4, 1e-2}) EXPECT_LT(preconditioned_spread(scene, gamma), 0.05) << "gamma " << gamma;
}

TEST(NewtonPreconditioner, CarriesTheCompliantPinsOfFlexiblePanels) {
  // The compliant hinges' five pin coordinates: their stiffness in B and
  // in the positions' back-substitution alike (where only B had it, 38 of
  // the 202 eigenvalues lay at up to 39). At long steps 12 still spread,
  // up to 8.7 at gamma 0.01 s: there the pins' gamma^2 K outweighs the
  // pin halves' inertia, so J B^-1 J^T lies far below the W of the
  // regulator's integral (with the pins' stiffness a hundredth, 0.14; README,
  // "Newton systems"; EliminatesTheLoopForcesExactly).
  const sim::Scene scene = test::scene_file("pantograph_flexible");
  EXPECT_LT(preconditioned_spread(scene, 1e-4), 0.05);
}

TEST(NewtonPreconditioner, EliminatesTheLoopForcesExactly) {
  // With the feedforward the residual's acceleration d carries W mu, which
  // cancels R's W in the loop-force rows: there J B^-1 J^T is exact, and
  // W is left only in the integral's scaling W R^-1. With the integral's
  // gains made negligible (p0 1e-9) pantograph_flexible's loops add no
  // spread to its tree's at long steps (measured 0.0141 / 0.0494 against
  // 0.0125 / 0.0479 without loops at gamma 1e-3 / 1e-2; with the integral
  // 0.082 / 7.7, and without the feedforward 0.86 / 1.0; with the loops
  // left to GMRES 5.6 / 400).
  const sim::Scene force_rows = test::scene_file("pantograph_flexible", {{"regulator.p0", "1e-9"}});
  const sim::Scene tree = test::scene_file("pantograph_flexible", {{"loops", "[]"}});
  for (const double gamma : {1e-3, 1e-2})
    EXPECT_LT(preconditioned_spread(force_rows, gamma), 1.25 * preconditioned_spread(tree, gamma)) << "gamma " << gamma;
}

TEST(NewtonPreconditioner, EliminatesTheLoopForcesExactlyWithTheLatchesEngaged) {
  // The generated 10-stage array deployed and latched (its 22 latches
  // engage near 6.1 s), at 7.5 s: the latches' gamma^2 K puts J B^-1 J^T
  // far below W along the loops, and with the integral the spread is
  // 0.205 / 4.7 at gamma 1e-3 / 1e-2 (the 30-stage array's 1.2 / 21).
  // With the integral's gains negligible, the force rows alone, it is
  // 5.5e-4 / 1.2e-3 (30 stages: 0.019 / 0.099).
  const sim::SceneFile file = studies::generate_pantograph(10);
  sim::RunSettings run = file.scene.run;
  run.t_end = 7.5;
  const sim::RunResult deployed = sim::simulate(file.scene, run, {}, sim::RunThreads::one);
  ASSERT_EQ(deployed.status, sim::RunStatus::finished);
  ASSERT_EQ(deployed.trajectory.events.size(), 22u);
  sim::Dynamics force_rows(sim::apply_overrides(file, {{"regulator.p0", "1e-9"}}).scene);
  for (const sim::LatchEvent& event : deployed.trajectory.events) force_rows.latch_state().engage(event.latch);
  for (const double gamma : {1e-3, 1e-2})
    EXPECT_LT(preconditioned_spread(force_rows, deployed.trajectory.samples.back().y, gamma), 0.05)
        << "gamma " << gamma;
}

}  // namespace
}  // namespace unfurl
