// The Krylov solvers' J v (Dynamics::jacobian_times) against a central
// difference of the exact right-hand side: it may leave out only how the
// regulator's gains turn with q.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

// A generic state (moving, loops slightly open) and direction.
struct Probe {
  std::vector<double> y, v;
};

Probe probe(sim::Dynamics& dynamics, bool along_q = true) {
  Probe p{dynamics.initial_state(), {}};
  p.v.resize(p.y.size());
  for (std::size_t k = 0; k < p.y.size(); ++k) {
    p.y[k] += 1e-3 * std::sin(1.0 + k);
    p.v[k] = std::cos(2.0 + 3.0 * k);
  }
  if (!along_q) std::fill_n(p.v.begin() + dynamics.layout().q(), dynamics.layout().nq, 0.0);
  return p;
}

// ||J v - (f(y + h v) - f(y - h v)) / 2h|| / ||J v||.
double relative_error(const sim::Scene& scene, bool along_q) {
  sim::Dynamics dynamics(scene);
  const Probe p = probe(dynamics, along_q);
  const std::size_t n = p.y.size();
  std::vector<double> Jv(n), plus(n), minus(n), y_plus(n), y_minus(n);
  EXPECT_TRUE(dynamics.jacobian_times(0, p.y.data(), p.v.data(), Jv.data()));
  const double h = 1e-6;
  for (std::size_t k = 0; k < n; ++k) y_plus[k] = p.y[k] + h * p.v[k], y_minus[k] = p.y[k] - h * p.v[k];
  dynamics.rhs(0, y_plus.data(), plus.data());
  dynamics.rhs(0, y_minus.data(), minus.data());
  Eigen::VectorXd difference(n), product = Eigen::Map<Eigen::VectorXd>(Jv.data(), n);
  for (std::size_t k = 0; k < n; ++k) difference[k] = (plus[k] - minus[k]) / (2 * h);
  return (product - difference).norm() / product.norm();
}

// Along p and u the gains stay put: J v is the right-hand side's own
// derivative, to the difference quotients' error with the dense solver and
// to the unrefined solve's (about 1e-5 of R^-1 b) with the sparse one.
TEST(JacobianTimes, IsExactAlongMomentaAndRegulatorStates) {
  EXPECT_LT(relative_error(test::scene_file("pantograph", {{"regulator.solver", "dense"}}), false), 1e-8);
  EXPECT_LT(relative_error(test::scene_file("pantograph", {{"regulator.solver", "sparse"}}), false), 1e-4);
}

// Along q it leaves out the gains' turn, -R^-1 (dR/dq v) lambda: a few
// per cent here, with the loops held 1e-3 open. A wrong sign or a missing
// term would be of order one.
TEST(JacobianTimes, LeavesOutOnlyTheGainsTurnAlongQ) {
  for (const char* solver : {"dense", "sparse"})
    EXPECT_LT(relative_error(test::scene_file("pantograph", {{"regulator.solver", solver}}), true), 0.1) << solver;
}

TEST(JacobianTimes, IsExactWithoutLoops) {
  EXPECT_LT(relative_error(test::scene_file("zfold"), true), 1e-6);
}

TEST(JacobianTimes, RepeatsAtOneBaseAndLeavesTheRightHandSideExact) {
  // Several products at one base (as GMRES asks), then f itself: the held
  // gains and the unrefined solves end with the product.
  const sim::Scene scene = test::scene_file("pantograph", {{"regulator.solver", "sparse"}});
  sim::Dynamics dynamics(scene), fresh(scene);
  const Probe p = probe(dynamics);
  const std::size_t n = p.y.size();
  std::vector<double> first(n), again(n), f(n), f_fresh(n);
  dynamics.jacobian_times(0, p.y.data(), p.v.data(), first.data());
  dynamics.jacobian_times(0, p.y.data(), p.v.data(), again.data());
  EXPECT_EQ(first, again);
  dynamics.rhs(0, p.y.data(), f.data());
  fresh.rhs(0, p.y.data(), f_fresh.data());
  EXPECT_EQ(f, f_fresh);
}

}  // namespace
}  // namespace unfurl
