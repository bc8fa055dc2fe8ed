// The loop forces the loads report, from W at one configuration: exact
// where W is well conditioned, without the null directions where it lacks
// rank, and the switch between the two (the Cholesky factor and the
// eigen-decomposition, closure_rank.hpp) as a run moves between them.
#include <gtest/gtest.h>

#include <Eigen/QR>

#include "closure_rank.hpp"

namespace unfurl::sim {
namespace {

constexpr int kM = 9;  // the pantograph's loop components

// W = S^-1 B S^-1 with B = Q diag(spectrum) Q^T: the spectrum is S W S's.
struct Closure {
  Eigen::VectorXd S = Eigen::VectorXd::LinSpaced(kM, 0.5, 4.0);  // 1/m on a linear component
  Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(kM, kM)).householderQ();

  LoopMatrix W(const Eigen::VectorXd& spectrum) const {
    const Eigen::MatrixXd B = Q * spectrum.asDiagonal() * Q.transpose();
    return S.cwiseInverse().asDiagonal() * B * S.cwiseInverse().asDiagonal();
  }
};

Eigen::VectorXd spread(double weakest) {
  Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(kM, 0.1, 1.0);
  lambda[0] = weakest;
  return lambda;
}

TEST(ClosureRank, AWellConditionedClosureGivesTheExactDeterminateLoopForces) {
  const Closure c;
  ClosureRank rank(c.S);
  const LoopMatrix W = c.W(spread(2e-2));
  rank.compute(W);
  const Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(kM, -1.0, 2.0);
  Eigen::VectorXd lambda(kM);
  rank.rigid_loop_forces(d.data(), lambda.data());
  EXPECT_LT((W * lambda - d).norm(), 1e-12 * d.norm());
  EXPECT_EQ(rank.rank(), kM);
  Eigen::VectorXd regulated = lambda;  // the regulator's agree
  EXPECT_TRUE(rank.loop_forces(d.data(), regulated.data(), true));
  EXPECT_LT((regulated - lambda).norm(), 1e-14 * lambda.norm());
}

TEST(ClosureRank, ARankDeficientClosureBetweenWellConditionedOnesLeavesItsNullDirectionOut) {
  const Closure c;
  ClosureRank rank(c.S);
  const Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(kM, -1.0, 2.0);
  Eigen::VectorXd lambda(kM);
  for (const double weakest : {2e-2, 1e-17, 2e-2}) {
    const LoopMatrix W = c.W(spread(weakest));
    rank.compute(W);
    lambda.setZero();
    const bool determinate = rank.loop_forces(d.data(), lambda.data(), true);
    const Eigen::VectorXd null = c.Q.col(0);  // of S W S; lambda~ = S^-1 lambda
    if (weakest > ClosureRank::kWeakDirection) {
      EXPECT_TRUE(determinate);
      EXPECT_EQ(rank.rank(), kM);
      EXPECT_LT((W * lambda - d).norm(), 1e-12 * d.norm());
    } else {
      EXPECT_FALSE(determinate) << "a self-stress along the null direction is not determined";
      EXPECT_EQ(rank.rank(), kM - 1);
      EXPECT_LT(std::abs(null.dot(lambda.cwiseQuotient(c.S))), 1e-12 * lambda.norm());
      // Along every other direction the rigid ones: W lambda = d there.
      const Eigen::VectorXd residual = c.S.asDiagonal() * (W * lambda - d);
      EXPECT_LT((residual - null.dot(residual) * null).norm(), 1e-12 * (c.S.asDiagonal() * d).norm());
    }
  }
}

}  // namespace
}  // namespace unfurl::sim
