#include "unfurl/sim/integrator.hpp"

#include <algorithm>
#include <cmath>

#include "arkode_integrators.hpp"
#include "cvode_integrator.hpp"
#include "rk4_integrator.hpp"

namespace unfurl::sim {

SolverStats& SolverStats::operator+=(const SolverStats& segment) {
  steps += segment.steps;
  jacobian_evals += segment.jacobian_evals;
  linear_setups += segment.linear_setups;
  linear_iterations += segment.linear_iterations;
  nonlinear_iterations += segment.nonlinear_iterations;
  nonlinear_failures += segment.nonlinear_failures;
  error_test_failures += segment.error_test_failures;
  restarts += segment.restarts;
  grazes += segment.grazes;
  min_step = std::min(min_step, segment.min_step);
  min_step_after_restart = std::min(min_step_after_restart, segment.min_step_after_restart);
  last_step = segment.last_step;
  return *this;
}

std::vector<double> absolute_tolerances(const Dynamics& dynamics, double atol) {
  std::vector<double> tol = dynamics.state_scale();
  for (double& t : tol) t *= atol;
  return tol;
}

bool uses_krylov(const RunSettings& settings, int state_size) {
  return settings.linear_solver == LinearSolverKind::krylov ||
         (settings.linear_solver == LinearSolverKind::automatic && state_size > kDenseStatesUpTo);
}

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind, Dynamics& dynamics,
                                            const RunSettings& settings, double t0,
                                            const std::vector<double>& y0) {
  switch (kind) {
    case IntegratorKind::cvode_bdf:
    case IntegratorKind::cvode_adams:
      return std::make_unique<CvodeIntegrator>(kind, dynamics, settings, t0, y0);
    case IntegratorKind::arkode_erk:
    case IntegratorKind::arkode_dirk:
      return std::make_unique<ArkodeIntegrator>(kind, dynamics, settings, t0, y0);
    case IntegratorKind::rk4:
      return std::make_unique<Rk4Integrator>(dynamics, settings, t0, y0);
  }
  return nullptr;
}

}  // namespace unfurl::sim
