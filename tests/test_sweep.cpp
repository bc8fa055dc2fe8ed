// The O(N) sweep against an independent formulation (dense_formulation.hpp):
// for random trees
//   q' must equal Mtilde^-1 (p - b)             (b: the base-motion terms)
//   p' must equal -dH/dq + Q                    (H by finite differences)
// where H = (p - b)^T Mtilde^-1 (p - b) / 2 - c + V(q).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
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
  const sim::Scene scene = random_tree(rng, N, GetParam() % 3 == 0);
  const int n = scene.model.nq;
  if (n == 0) GTEST_SKIP() << "only fixed joints";
  ASSERT_EQ(n, scene.model.nv);
  sim::Dynamics dynamics(scene);
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

// Trees with ball, planar, free and universal joints (quaternions in q,
// the child's own rates as velocity coordinates): the rates
// w = Mtilde^-1 (p - b) with A from the test's own placements; q' = N(q) w,
// a quaternion's by the test's own product q (x) (0, w) / 2; and
// p' = -dH/dq + Q for every coordinate whose rate is its q' (one-coordinate
// and universal joints: there p is conjugate to q, and a ball's or free
// joint's map from its rates to its q' does not involve them). A universal
// joint's A turns with q: this is its dA^T mu of (7).
class RandomMultiDofTrees : public ::testing::TestWithParam<int> {};

TEST_P(RandomMultiDofTrees, SweepMatchesTheDenseFormulation) {
  std::mt19937 rng(1000 + GetParam());
  const int N = 1 + GetParam() % 20;
  const sim::Scene scene = random_tree(rng, N, GetParam() % 3 == 0, true);
  const sim::Model& model = scene.model;
  const int nq = model.nq, nv = model.nv;
  if (nv == 0) GTEST_SKIP() << "only fixed joints";
  if (!model.has_multi_dof_joints()) GTEST_SKIP() << "no joint of several coordinates drawn";
  sim::Dynamics dynamics(scene);
  std::uniform_real_distribution<double> U(-1, 1);
  VectorXd y(nq + nv);
  for (int k = 0; k < nq; ++k) y[k] = scene.q0[k];
  for (int k = 0; k < nv; ++k) y[nq + k] = 5 * U(rng);
  VectorXd ydot(nq + nv);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  const VectorXd q = y.head(nq), p = y.tail(nv);

  const Dense d = dense_formulation(scene, q);
  const VectorXd w = d.Mt.ldlt().solve(p - d.b);
  VectorXd dq_expected(nq);
  for (int i = 0; i < model.size(); ++i) {
    const sim::Joint& j = model.joints[i];
    const int c = model.first_position[i].value, v = model.first_velocity[i].value;
    if (c < 0) continue;
    const auto quaternion_rate = [&](int at, int rate) {
      const Eigen::Vector4d r = 0.5 * quaternion_product(q.segment<4>(at), Eigen::Vector4d(0, w[rate], w[rate + 1], w[rate + 2]));
      dq_expected.segment<4>(at) = r;
    };
    if (j.is_scalar() || j.type == sim::JointType::universal || j.compliant) {
      for (int k = 0; k < j.dof(); ++k) dq_expected[c + k] = w[v + k];
    } else if (j.type == sim::JointType::spherical) {
      quaternion_rate(c, v);
    } else if (j.type == sim::JointType::free) {
      dq_expected.segment<3>(c) = quaternion_matrix(&q[c + 3]) * w.segment<3>(v);
      quaternion_rate(c + 3, v + 3);
    } else {  // planar: x' = R (u1 e1 + u2 e2) in the plane's coordinates
      const double co = std::cos(q[c + 2]), si = std::sin(q[c + 2]);
      dq_expected[c] = co * w[v] - si * w[v + 1];
      dq_expected[c + 1] = si * w[v] + co * w[v + 1];
      dq_expected[c + 2] = w[v + 2];
    }
  }
  EXPECT_LT(relative_error(ydot.head(nq), dq_expected), 1e-7) << N << " bodies";

  // (position index, velocity index) of every coordinate conjugate to its p.
  std::vector<std::pair<int, int>> conjugate;
  for (int i = 0; i < model.size(); ++i)
    if (model.joints[i].is_scalar() || model.joints[i].type == sim::JointType::universal ||
        model.joints[i].compliant)
      for (int k = 0; k < model.joints[i].dof(); ++k)
        conjugate.emplace_back(model.first_position[i].value + k, model.first_velocity[i].value + k);
  const double h = 1e-4;
  const VectorXd Q = applied_forces(scene, q, w);
  double scale = 1;
  std::vector<double> dp_expected;
  for (const auto& [cq, cv] : conjugate) {
    auto H_at = [&, cq = cq](double dx) {
      VectorXd qs = q;
      qs[cq] += dx;
      return hamiltonian(scene, qs, p);
    };
    dp_expected.push_back(Q[cv] - (-H_at(2 * h) + 8 * H_at(h) - 8 * H_at(-h) + H_at(-2 * h)) / (12 * h));
    scale = std::max(scale, std::abs(dp_expected.back()));
  }
  for (std::size_t k = 0; k < conjugate.size(); ++k)
    EXPECT_NEAR(ydot[nq + conjugate[k].second], dp_expected[k], 1e-7 * scale)
        << "p' of " << model.velocity_name(conjugate[k].second) << ", " << N << " bodies";
}

INSTANTIATE_TEST_SUITE_P(UpTo20Bodies, RandomMultiDofTrees, ::testing::Range(1, 31));

TEST(Sweep, LoopMobilityFromExtraPassesEqualsDenseFormula) {
  // W = eps T A Mtilde^-1 (eps T A)^T on the active components, by the
  // regulator's m passes of the sweep and densely.
  const sim::Scene scene = test::scene_file("pantograph");
  sim::Dynamics dynamics(scene);
  sim::Regulator& regulator = *dynamics.regulator();
  const int n = scene.model.nq, m = regulator.size();
  VectorXd q(n);
  for (int k = 0; k < n; ++k) q[k] = 0.7 * scene.q0[k];
  sim::Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  const MatrixXd W = regulator.mobility(sweep);

  const MatrixXd W_dense = dense_mobility(scene, regulator.components(), q);
  EXPECT_LT((W - W_dense).norm(), 1e-10 * W_dense.norm());
  EXPECT_EQ(m, W.rows());
}

// The force pass along root paths (how the regulator finds its components)
// gives the whole tree's pass exactly on those paths' coordinates: a wrench
// pair on a loop's two halves of pantograph_flexible, whose loops close
// through its plates' nodes.
TEST(Sweep, AForcePassAlongRootPathsIsTheWholePassThere) {
  const sim::Scene scene = test::scene_file("pantograph_flexible");
  const sim::Model& model = scene.model;
  sim::Sweep sweep(model);
  std::vector<double> q = scene.q0;
  for (int c = 0; c < model.nq; ++c) q[c] += 0.01 * c;
  sweep.set_configuration(q.data());
  ASSERT_FALSE(scene.loops.empty());
  for (const sim::Loop& loop : scene.loops) {
    std::vector<int> path;
    for (const int end : {loop.body, loop.image})
      for (int i = end; i >= 0; i = model.parent[i])
        if (std::find(path.begin(), path.end(), i) == path.end()) path.push_back(i);
    std::sort(path.begin(), path.end(), std::greater<int>());
    std::vector<sim::Vec6> F(model.size(), sim::Vec6::Zero()), F_along = F;
    F[loop.body] = sim::Vec6::LinSpaced(-1, 2);
    F[loop.image] = sim::Vec6::LinSpaced(3, -0.5);
    F_along = F;
    VectorXd Q(model.nv), Q_along = VectorXd::Constant(model.nv, std::nan(""));
    sweep.generalized_forces(F, Q.data());
    sweep.generalized_forces_along(path, F_along, Q_along.data());
    int written = 0;
    for (int c = 0; c < model.nv; ++c) {
      if (std::isnan(Q_along[c])) {
        EXPECT_EQ(Q[c], 0) << "coordinate " << c << " off the paths";
      } else {
        EXPECT_EQ(Q_along[c], Q[c]) << "coordinate " << c;
        ++written;
      }
    }
    EXPECT_GT(written, 0);
  }
}

TEST(Sweep, JointDiagonalSolvesWithMassMatrixPlusDiagonal) {
  // The preconditioner's passes: (Mtilde + diag k) dq = p.
  const sim::Scene scene = test::scene_file("pantograph");
  const int n = scene.model.nq;
  VectorXd q(n), k(n), p = VectorXd::LinSpaced(n, -1, 2);
  for (int c = 0; c < n; ++c) {
    q[c] = 0.6 * scene.q0[c] + 0.05 * c;
    k[c] = 0.3 + 0.1 * c;
  }
  sim::Sweep sweep(scene.model);
  sweep.set_configuration(q.data(), k.data());
  std::vector<sim::Vec6> phi(scene.model.size()), v(scene.model.size());
  VectorXd dq(n);
  sweep.bias(p.data(), phi);
  sweep.velocities(p.data(), phi, sim::Vec6::Zero(), dq.data(), v);
  MatrixXd K = dense_formulation(scene, q).Mt;
  K.diagonal() += k;
  EXPECT_LT(relative_error(dq, K.ldlt().solve(p)), 1e-12);
}

}  // namespace
}  // namespace unfurl
