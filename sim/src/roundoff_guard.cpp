#include "roundoff_guard.hpp"

#include <algorithm>

namespace unfurl::sim {

RoundoffGuard::RoundoffGuard(const Scene& scene, double rtol, double atol)
    : probe_(scene),
      fastest_rate_(std::max(probe_.scales().rate, probe_.regulator() ? probe_.regulator()->v_max() : 0.0)),
      rtol_(rtol),
      atol_(atol) {}

double RoundoffGuard::floor_at(double t, const std::vector<double>& y, const Dynamics& run) {
  probe_.latch_state() = run.latch_state();
  return roundoff_floor(probe_, t, y);
}

bool RoundoffGuard::step_taken(double t, const std::vector<double>& y, const Dynamics& run, Integrator& integrator) {
  const SolverStats s = integrator.stats();
  short_steps_ = integrator.last_step() * fastest_rate_ < kShortStep ? short_steps_ + 1 : 0;
  const bool shrunk = short_steps_ >= kSteps;
  if (!shrunk && s.nonlinear_failures - failures_seen_ < kFailures) return false;
  const bool often = s.steps - steps_seen_ <= kSteps;
  failures_seen_ = s.nonlinear_failures;
  steps_seen_ = s.steps;
  short_steps_ = 0;
  if (!often && !shrunk) return false;
  const double floor = floor_at(t, y, run);
  // Where Newton fails, doubled at most at a time: the least raise that
  // stops the failures. Where the steps shrank, to the floor at once.
  const double tolerance = std::max(rtol_, atol_);
  const double raised = std::min(floor * kMargin, shrunk ? std::max(2 * tolerance, floor) : 2 * tolerance);
  const double rtol = std::max(rtol_, raised), atol = std::max(atol_, raised);
  if (!above_tolerance(floor) || !integrator.set_tolerances(rtol, atol)) return false;
  rtol_ = rtol;
  atol_ = atol;
  raises_.push_back({t, floor, rtol_, atol_});
  return true;
}

}  // namespace unfurl::sim
