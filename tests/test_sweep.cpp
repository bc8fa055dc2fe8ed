// The O(N) sweep against an independent formulation (dense_formulation.hpp):
// for random trees
//   q' must equal Mtilde^-1 (p - b)             (b: the base-motion terms)
//   p' must equal -dH/dq + Q                    (H by finite differences)
// where H = (p - b)^T Mtilde^-1 (p - b) / 2 - c + V(q).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "closure_solver.hpp"
#include "dynamics.hpp"
#include "scene_generators.hpp"
#include "dense_formulation.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using namespace test;

double relative_error(const VectorXd& x, const VectorXd& reference) {
  return (x - reference).norm() / std::max(reference.norm(), 1e-300);
}

class RandomTrees : public ::testing::TestWithParam<int> {};

TEST_P(RandomTrees, SweepMatchesTheDenseHamiltonianFormulation) {
  std::mt19937 rng(GetParam());
  const int N = 1 + GetParam() % 30;
  const Scene scene = random_tree(rng, N, GetParam() % 3 == 0);
  const int n = scene.model.nq;
  if (n == 0) GTEST_SKIP() << "only fixed joints";
  Dynamics dynamics(scene);
  std::uniform_real_distribution<double> U(-1, 1);
  VectorXd y(2 * n);
  for (int k = 0; k < n; ++k) {
    y[k] = scene.q0[k];
    y[n + k] = 5 * U(rng);
  }
  VectorXd ydot(2 * n);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  const VectorXd q = y.head(n), p = y.tail(n);

  const Dense d = dense_formulation(scene, q);
  const VectorXd dq_expected = d.Mt.ldlt().solve(p - d.b);
  EXPECT_LT(relative_error(ydot.head(n), dq_expected), 1e-7) << N << " bodies";

  // -dH/dq by fourth-order central differences.
  VectorXd dp_expected(n);
  const double h = 1e-4;
  for (int k = 0; k < n; ++k) {
    auto H_at = [&](double dx) {
      VectorXd qs = q;
      qs[k] += dx;
      return hamiltonian(scene, qs, p);
    };
    dp_expected[k] = -(-H_at(2 * h) + 8 * H_at(h) - 8 * H_at(-h) + H_at(-2 * h)) / (12 * h);
  }
  dp_expected += applied_forces(scene, q, dq_expected);
  EXPECT_LT(relative_error(ydot.tail(n), dp_expected), 1e-7) << N << " bodies";
}

INSTANTIATE_TEST_SUITE_P(UpTo30Bodies, RandomTrees, ::testing::Range(1, 41));

// W = J Mtilde^-1 J^T with J = eps T A from the dense formulation.
MatrixXd dense_mobility(const Scene& scene, const std::vector<LoopComponent>& components, const VectorXd& q) {
  const Dense d = dense_formulation(scene, q);
  const int m = static_cast<int>(components.size());
  // eps T A = rows of (A^T T^T eps^T)^T; ATTt maps a body force to Q.
  MatrixXd J(m, scene.model.nq);
  for (int c = 0; c < m; ++c) {
    const LoopComponent& lc = components[c];
    VectorXd F = VectorXd::Zero(6 * scene.model.size());
    F[6 * scene.loops[lc.loop].body + lc.axis] = 1;
    F[6 * scene.loops[lc.loop].image + lc.axis] = -1;
    J.row(c) = (d.ATTt * F).transpose();
  }
  return J * d.Mt.ldlt().solve(J.transpose());
}

TEST(Sweep, LoopMobilityFromExtraPassesEqualsDenseFormula) {
  // W = eps T A Mtilde^-1 (eps T A)^T on the active components, by the
  // regulator's m passes of the sweep and densely.
  const Scene scene = test::scene_file("pantograph");
  Dynamics dynamics(scene);
  Regulator& regulator = *dynamics.regulator();
  const int n = scene.model.nq, m = regulator.size();
  VectorXd q(n);
  for (int k = 0; k < n; ++k) q[k] = 0.7 * scene.q0[k];
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  const MatrixXd W = regulator.mobility(sweep);

  const MatrixXd W_dense = dense_mobility(scene, regulator.components(), q);
  EXPECT_LT((W - W_dense).norm(), 1e-10 * W_dense.norm());
  EXPECT_EQ(m, W.rows());
}

TEST(Sweep, JointDiagonalSolvesWithMassMatrixPlusDiagonal) {
  // The preconditioner's passes: (Mtilde + diag k) dq = p.
  const Scene scene = test::scene_file("pantograph");
  const int n = scene.model.nq;
  VectorXd q(n), k(n), p = VectorXd::LinSpaced(n, -1, 2);
  for (int c = 0; c < n; ++c) {
    q[c] = 0.6 * scene.q0[c] + 0.05 * c;
    k[c] = 0.3 + 0.1 * c;
  }
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data(), k.data());
  std::vector<Vec6> phi(scene.model.size()), v(scene.model.size());
  VectorXd dq(n);
  sweep.bias(p.data(), phi);
  sweep.velocities(p.data(), phi, Vec6::Zero(), dq.data(), v);
  MatrixXd K = dense_formulation(scene, q).Mt;
  K.diagonal() += k;
  EXPECT_LT(relative_error(dq, K.ldlt().solve(p)), 1e-12);
}

// R^-1 b = (W + delta I)^-1 b by a closure solver at q, and densely.
void expect_closure_solve_matches_dense(const Scene& scene, ClosureSolverKind kind, const VectorXd& q,
                                        double delta) {
  Dynamics dynamics(scene);
  const std::vector<LoopComponent>& components = dynamics.regulator()->components();
  const int m = static_cast<int>(components.size());
  const auto solver = make_closure_solver(kind, scene.model, scene.loops, components);
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  ASSERT_TRUE(solver->factorize(sweep, delta));
  // Two right-hand sides at once, as the regulator solves them.
  MatrixXd B(m, 2);
  B.col(0) = VectorXd::LinSpaced(m, -1, 1) + VectorXd::Constant(m, 0.25);
  B.col(1) = VectorXd::LinSpaced(m, 2, -0.5);
  MatrixXd X(m, 2);
  solver->solve(B.data(), X.data(), 2);
  MatrixXd R = dense_mobility(scene, components, q);
  R.diagonal().array() += delta;
  for (int c = 0; c < 2; ++c)
    EXPECT_LT(relative_error(X.col(c), R.ldlt().solve(B.col(c))), 1e-9) << m << " components, delta " << delta;
}

TEST(ClosureSolver, DenseAndSparseSolveWithWPlusDelta) {
  const Scene scene = test::scene_file("pantograph");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.7 * scene.q0[k];
  for (const auto kind : {ClosureSolverKind::dense, ClosureSolverKind::sparse})
    expect_closure_solve_matches_dense(scene, kind, q, 1e-5);
}

TEST(ClosureSolver, SparseHoldsAtTheDeployedBranchPoint) {
  // At q = 0 W loses rank: R = W + delta I is what keeps the solve defined.
  const Scene scene = test::scene_file("pantograph");
  const VectorXd q = VectorXd::Zero(scene.model.nq);
  for (const double delta : {1e-3, 1e-5, 1e-7})
    expect_closure_solve_matches_dense(scene, ClosureSolverKind::sparse, q, delta);
}

TEST(ClosureSolver, SparseOnTenLoops) {
  const Scene scene = load_scene_text(generate_pantograph(10), "pantograph_10");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.5 * scene.q0[k];
  expect_closure_solve_matches_dense(scene, ClosureSolverKind::sparse, q, 1e-5);
}

}  // namespace
}  // namespace unfurl
