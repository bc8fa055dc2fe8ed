// One interface over the time integrators: SUNDIALS' CVODE (BDF, Adams),
// ARKODE (explicit adaptive RK, DIRK) and a fixed-step RK4. The simulation
// drives them one internal step at a time, so it can sample by their
// interpolation, handle latch events and cancel between steps.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/scene.hpp"

namespace unfurl::sim {

struct SolverStats {
  long steps = 0;
  long jacobian_evals = 0;
  long linear_setups = 0;
  long linear_iterations = 0;  // Krylov iterations (0 for a direct solver)
  long nonlinear_iterations = 0;
  long nonlinear_failures = 0;
  long error_test_failures = 0;
  long restarts = 0;  // re-initializations after latch events
  long grazes = 0;    // latch crossings found inside a step (latch_events.hpp)
  // The smallest step away from restarts (after each (re)start the step
  // grows from a tiny first step; those steps are counted apart).
  double min_step = std::numeric_limits<double>::infinity();
  double min_step_after_restart = std::numeric_limits<double>::infinity();
  double last_step = 0;

  // Counters of a run made of several restarted segments.
  SolverStats& operator+=(const SolverStats& segment);
};

enum class StepStatus { advanced, root, reached_stop, failed };

struct StepOutcome {
  StepStatus status = StepStatus::advanced;
  double t = 0;         // where the step (or the root) is
  std::string reason;   // for a failure
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // One internal step toward t_stop, never past it. Stops early at a root
  // of the latch switching functions (status root, t = the root).
  virtual StepOutcome step(double t_stop) = 0;
  // The span over which the interpolant serves: the last step taken (after
  // a root return it reaches past the root).
  virtual double span_begin() const { return span_end() - last_step(); }
  virtual double span_end() const = 0;
  // The state at a time inside the span, by the method's interpolant, and
  // its time derivative.
  virtual void interpolate(double t, double* y) = 0;
  virtual void interpolate_rate(double t, double* ydot) = 0;
  // The highest degree of the polynomial in t that the interpolant follows
  // over a step.
  virtual int interpolation_degree() const = 0;
  // Restarts cleanly from (t, y): after an event changed the equations.
  virtual void restart(double t, const double* y) = 0;
  // The switching functions that reached zero at the last root.
  virtual std::vector<int> roots() = 0;
  // Counters; min_step and restarts are the simulation's to fill.
  virtual SolverStats stats() const = 0;
  // Tolerances from the next restart on: rtol, and atol in the state's own
  // scales as absolute_tolerances() (SUNDIALS sets up its error weights
  // only when it starts). False for a method without error control (the
  // fixed-step RK4).
  virtual bool set_tolerances(double /*rtol*/, double /*atol*/) { return false; }
  // From now on, lower the order where it would step beyond its stability
  // limit (RunSettings::stability_limit_detection; only BDF has one to watch).
  virtual void watch_stability_limit() {}
  // From now on, step at this order or below (RunSettings::
  // max_order_after_latch; only BDF's order is capped).
  virtual void limit_order(int /*order*/) {}
  // The step it will try next, and the one just taken.
  virtual double current_step() const = 0;
  virtual double last_step() const = 0;
};

// Absolute tolerances per state in the mechanism's own sizes: atol x
// Dynamics::state_scale() (atol for an angle, atol x length for a length;
// for a momentum, what drifts its coordinate by as much over pi / rate;
// for the regulator's state, as its gap's).
std::vector<double> absolute_tolerances(const Dynamics& dynamics, double atol);

// Whether an implicit integrator uses GMRES for this state size.
bool uses_krylov(const RunSettings& settings, int state_size);

std::unique_ptr<Integrator> make_integrator(IntegratorKind kind, Dynamics& dynamics,
                                            const RunSettings& settings, double t0,
                                            const std::vector<double>& y0);

}  // namespace unfurl::sim
