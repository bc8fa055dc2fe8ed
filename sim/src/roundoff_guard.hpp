// Keeps an adaptive integrator from chasing the right-hand side's
// round-off. Where the Newton iteration keeps failing (kFailures failures
// within kSteps steps), the floor of f's round-off (roundoff_floor.hpp) is
// measured at that state with the run's latches; if kMargin times it lies
// above the larger of rtol and atol, both are raised to one value, the
// least that stops the failures (at most twice the larger, never above
// kMargin times the floor), and the raise is recorded. Below the floor no
// step fits the noise inside the error test: the pantograph latched at its
// branch point took 33,332 steps (10,904 Newton failures) at atol 1e-12
// against a floor of up to 1.7e-10. Runs whose Newton iterations converge
// are not measured and run as they did: the four-bar at rtol 1e-8, whose
// floor samples reach 1.1e-8 but whose Newton iteration fails once in 400
// steps, keeps its gap of 6.4e-10 m over 200 s (2.2e-9 m when raised).
#pragma once

#include <algorithm>
#include <vector>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/integrator.hpp"
#include "unfurl/sim/roundoff_floor.hpp"
#include "unfurl/sim/tolerance_raise.hpp"

namespace unfurl::sim {

class RoundoffGuard {
 public:
  // Step counts jump where atol falls to about 1.2 times the floor (an
  // estimate of about 2.5 sigma whose samples along a run scatter by 3x).
  static constexpr double kMargin = 2.0;
  // A look after kFailures Newton failures within at most kSteps steps (a
  // probe costs seven evaluations of f); the pantograph latched below its
  // floor fails one step in three, the generated 100-stage array started
  // below its floor one in 17 (at kSteps 100 it ran 4 ms, 1,700 steps,
  // before a look), a run above its floor one in hundreds (the four-bar at
  // rtol 1e-8: one in 385 over 20 s). Error-test failures are not counted:
  // that four-bar fails one step in ten on them, and counted they raised its
  // tolerances and the pantograph's before its latch-up.
  static constexpr long kFailures = 10;
  static constexpr long kSteps = 200;

  RoundoffGuard(const Scene& scene, double rtol, double atol);

  // The floor at the initial state, reported only: a run below it at the
  // start need not fail (the pantograph at rtol 1e-11 reaches its latch-up
  // with the hinge peaks of a run at 1e-10 to 1e-4; 6 times the steps).
  double floor_at_start(double t, const std::vector<double>& y) { return roundoff_floor(probe_, t, y); }

  // After a step that ended at (t, y), with the run's latches in `run`;
  // true where it raised the tolerances (the integrator is to restart there).
  bool step_taken(double t, const std::vector<double>& y, const Dynamics& run, Integrator& integrator);

  // The floor at (t, y) with the run's latches (the end of a run).
  double floor_at(double t, const std::vector<double>& y, const Dynamics& run);

  const std::vector<ToleranceRaise>& raises() const { return raises_; }

 private:
  // Whether a floor lies above what the tolerances resolve: the larger of
  // rtol and atol, the measure the floor is in (a state near its own scale
  // is held to rtol, one near zero to atol).
  bool above_tolerance(double floor) const { return floor * kMargin > std::max(rtol_, atol_); }

  Dynamics probe_;  // its own counts and caches, so the run's are untouched
  double rtol_;
  double atol_;
  long failures_seen_ = 0, steps_seen_ = 0;  // where the failures were last counted from
  std::vector<ToleranceRaise> raises_;
};

}  // namespace unfurl::sim
