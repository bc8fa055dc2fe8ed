// The O(N) sweep against an independent formulation (dense_formulation.hpp):
// for random trees
//   q' must equal Mtilde^-1 (p - b)             (b: the base-motion terms)
//   p' must equal -dH/dq + Q                    (H by finite differences)
// where H = (p - b)^T Mtilde^-1 (p - b) / 2 - c + V(q).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "unfurl/sim/dynamics.hpp"
#include "dense_formulation.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using namespace test;

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

}  // namespace
}  // namespace unfurl
