// Checks a closure solver's R^-1 b against the dense formulation's W.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "dense_formulation.hpp"
#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/dynamics.hpp"

namespace unfurl::test {

// R^-1 b = (W + delta I)^-1 b by a closure solver at q, and densely.
inline void expect_closure_solve_matches_dense(const sim::Scene& scene, sim::ClosureSolverKind kind, const VectorXd& q,
                                               double delta) {
  sim::Dynamics dynamics(scene);
  const std::vector<sim::LoopComponent>& components = dynamics.regulator()->components();
  const int m = static_cast<int>(components.size());
  const auto solver = sim::make_closure_solver(kind, scene.model, scene.loops, components);
  sim::Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  const VectorXd deltas = VectorXd::Constant(m, delta);
  ASSERT_TRUE(solver->factorize(sweep, deltas.data()));
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

}  // namespace unfurl::test
