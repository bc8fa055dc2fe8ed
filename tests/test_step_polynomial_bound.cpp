// The latch events pass over a step's graze search where a bound on the
// switching function's interpolant stays clear of zero. The bound must be
// a bound: below every value of any polynomial of its degree, and each
// integrator's interpolant must be a polynomial of no more than the degree
// it declares (else the bound would be of another curve).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "step_polynomial_bound.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/integrator.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace unfurl {
namespace {

// p(u) = sum c_j u^j.
double polynomial(const Eigen::VectorXd& c, double u) {
  double p = 0;
  for (int j = static_cast<int>(c.size()) - 1; j >= 0; --j) p = p * u + c[j];
  return p;
}

TEST(StepPolynomialBound, LiesBelowEveryValueOfRandomPolynomials) {
  std::mt19937 random(3);
  std::normal_distribution<double> coefficient;
  for (const int d : {3, 5, 12}) {
    const sim::StepPolynomialBound bound(d);
    for (int trial = 0; trial < 200; ++trial) {
      Eigen::VectorXd c(d + 1), values(d + 1);
      for (int j = 0; j <= d; ++j) c[j] = coefficient(random);
      for (int k = 0; k <= d; ++k) values[k] = polynomial(c, bound.node(k));
      double least = std::numeric_limits<double>::infinity();
      for (int i = 0; i <= 4000; ++i) least = std::min(least, polynomial(c, i / 4000.0));
      EXPECT_LE(bound.lower_bound(values), least + 1e-12 * c.cwiseAbs().sum()) << "degree " << d;
    }
  }
}

TEST(StepPolynomialBound, SeesAPolynomialClearOfZeroAsClear) {
  // 1 - u + u^2 (least value 3/4): its Bernstein coefficients at degree 5
  // are 1, 4/5, 7/10, 7/10, 4/5, 1.
  const sim::StepPolynomialBound bound(5);
  Eigen::VectorXd values(6);
  for (int k = 0; k <= 5; ++k) values[k] = 1 - bound.node(k) + bound.node(k) * bound.node(k);
  EXPECT_NEAR(bound.lower_bound(values), 0.7, 1e-12);
  EXPECT_EQ(bound.node(0), 0.0);
  EXPECT_EQ(bound.node(5), 1.0);
}

// Lagrange's polynomial through (u_k, x_k), at u.
double lagrange(const std::vector<double>& u, const std::vector<double>& x, double at) {
  double p = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    double l = 1;
    for (std::size_t j = 0; j < u.size(); ++j)
      if (j != k) l *= (at - u[j]) / (u[k] - u[j]);
    p += l * x[k];
  }
  return p;
}

TEST(StepPolynomialBound, EachIntegratorsInterpolantIsAPolynomialOfTheDegreeItDeclares) {
  const sim::Scene scene = sim::load_builtin_scene("pantograph");
  for (const sim::IntegratorKind kind : {sim::IntegratorKind::cvode_bdf, sim::IntegratorKind::cvode_adams,
                                         sim::IntegratorKind::arkode_erk, sim::IntegratorKind::arkode_dirk,
                                         sim::IntegratorKind::rk4}) {
    sim::Dynamics dynamics(scene);
    sim::RunSettings settings = scene.run;
    settings.integrator = kind;
    const std::vector<double> y0 = dynamics.initial_state();
    const auto integrator = sim::make_integrator(kind, dynamics, settings, 0.0, y0);
    const int d = integrator->interpolation_degree();
    const sim::StepPolynomialBound bound(d);
    std::vector<double> y(y0.size());
    double worst = 0;
    // 2000 steps: CVODE's BDF reaches order 5 on the way, and a degree
    // declared one lower fails here (as RK4's does).
    for (int n = 0; n < 2000; ++n) {
      ASSERT_NE(integrator->step(5.0).status, sim::StepStatus::failed);
      const double lo = integrator->span_begin(), hi = integrator->span_end();
      if (!(hi > lo)) continue;
      std::vector<double> u(d + 1);
      std::vector<std::vector<double>> at_nodes(d + 1);
      for (int k = 0; k <= d; ++k) {
        u[k] = bound.node(k);
        at_nodes[k].resize(y0.size());
        integrator->interpolate(lo + u[k] * (hi - lo), at_nodes[k].data());
      }
      for (const double at : {0.137, 0.5, 0.861}) {
        integrator->interpolate(lo + at * (hi - lo), y.data());
        for (std::size_t i = 0; i < y.size(); ++i) {
          std::vector<double> x(d + 1);
          double size = std::abs(y[i]);
          for (int k = 0; k <= d; ++k) size = std::max(size, std::abs(x[k] = at_nodes[k][i]));
          if (size > 0) worst = std::max(worst, std::abs(lagrange(u, x, at) - y[i]) / size);
        }
      }
    }
    EXPECT_LT(worst, 1e-9) << "integrator " << static_cast<int>(kind) << ", degree " << d;
  }
}

}  // namespace
}  // namespace unfurl
