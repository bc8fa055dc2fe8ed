#include "roundoff_guard.hpp"

#include <algorithm>

namespace unfurl::sim {

RoundoffGuard::RoundoffGuard(const Scene& scene, double rtol, double atol) : probe_(scene), rtol_(rtol), atol_(atol) {}

double RoundoffGuard::floor_at(double t, const std::vector<double>& y, const Dynamics& run) {
  probe_.latch_state() = run.latch_state();
  return roundoff_floor(probe_, t, y);
}

bool RoundoffGuard::step_taken(double t, const std::vector<double>& y, const Dynamics& run, Integrator& integrator) {
  const SolverStats s = integrator.stats();
  if (s.nonlinear_failures - failures_seen_ < kFailures) return false;
  const bool often = s.steps - steps_seen_ <= kSteps;
  failures_seen_ = s.nonlinear_failures;
  steps_seen_ = s.steps;
  if (!often) return false;
  const double floor = floor_at(t, y, run);
  // Doubled at most at a time: the least raise that stops the failures.
  const double raised = std::min(floor * kMargin, 2 * std::max(rtol_, atol_));
  const double rtol = std::max(rtol_, raised), atol = std::max(atol_, raised);
  if (!above_tolerance(floor) || !integrator.set_tolerances(rtol, atol)) return false;
  rtol_ = rtol;
  atol_ = atol;
  raises_.push_back({t, floor, rtol_, atol_});
  return true;
}

}  // namespace unfurl::sim
