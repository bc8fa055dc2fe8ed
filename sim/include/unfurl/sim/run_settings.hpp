// How a scene is run: the integrator, its tolerances, the output interval
// and the limits that stop a run.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace unfurl::sim {

enum class IntegratorKind { cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, rk4 };

// How the implicit integrators solve their Newton systems: a dense
// finite-difference Jacobian and LU (O(n^3) per setup), or GMRES with an
// O(N) preconditioner (newton_preconditioner.hpp). automatic: dense up to
// kDenseStatesUpTo states.
enum class LinearSolverKind { automatic, dense, krylov };
// When CVODE's BDF watches for its stability limit (RunSettings).
enum class StabilityLimitDetection { off, on, after_latch };
inline constexpr int kDenseStatesUpTo = 100;
inline constexpr int kBdfMaxOrder = 5;  // CVODE's, and its default

const char* integrator_name(IntegratorKind kind);
// Parses "cvode-bdf" etc.; nullopt for an unknown name.
std::optional<IntegratorKind> parse_integrator(const std::string& name);
// As a scene file spells it: false, true, after_latch.
const char* stability_limit_detection_name(StabilityLimitDetection detection);
std::optional<StabilityLimitDetection> parse_stability_limit_detection(const std::string& name);
const std::vector<IntegratorKind>& all_integrators();

struct RunSettings {
  double t_end = 10;
  IntegratorKind integrator = IntegratorKind::cvode_bdf;
  double rtol = 1e-8;
  // For an angle; a length counts in the mechanism's length, the other
  // states in its own sizes (absolute_tolerances(), integrator.hpp).
  double atol = 1e-10;
  LinearSolverKind linear_solver = LinearSolverKind::automatic;
  double dt = 1e-4;     // step of the fixed-step RK4
  double sample = 0.01; // output interval
  long max_steps = 50'000'000;
  // A run that would store more samples (t_end / sample) is refused before
  // it starts: a sample of a large array holds kilobytes.
  long max_samples = 1'000'000;
  // The run fails ("time budget") when it has taken longer than this, in
  // seconds of wall time; 0: no limit.
  double max_wall_time = 0;
  // The run fails when a loop's geometric gap exceeds this (rad, or a
  // distance over the mechanism's length), at the end of any step: the
  // regulator has lost the loop.
  double max_closure = 0.1;
  // Latches whose roots follow the first within this many seconds engage in
  // one restart, each at its own root (latch_events.hpp).
  double event_window = 1e-6;
  // Whether an adaptive run raises its tolerances where its Newton
  // iteration keeps failing on the right-hand side's round-off
  // (roundoff_guard.hpp in the sources); off, it holds them however many
  // steps that takes (a reference solution, a work-precision study).
  bool roundoff_guard = true;
  // Whether CVODE's BDF watches for its stability limit (CVodeSetStabLimDet)
  // and lowers its order there: orders 3 to 5 are not stable on lightly
  // damped modes near the imaginary axis, such as a latched array ringing
  // down, and stepping under that limit costs steps. Off by default: on a
  // scene without such modes it can lower the order for nothing (the
  // spinning beam took 2.6 times the steps). after_latch watches from the
  // first latch's engagement on, so the deployment is stepped as without
  // it and only the ring-down is watched. Other integrators ignore it.
  StabilityLimitDetection stability_limit_detection = StabilityLimitDetection::off;
  // CVODE BDF's highest order from the first latch's engagement on. At 2
  // BDF is A-stable: no lightly damped mode holds its steps short, as order
  // 4 held a 30-stage array's ring-down at rest to 2.2e-4 s steps (68,478
  // steps over 20 s at rtol 1e-7; 4,459 capped at 2, the same answer to
  // 2.9e-8 rad). It costs steps wherever the ring-down is not held so (the
  // pantograph at rtol 1e-8: 6,316 against 1,860), hence no cap by default
  // (kBdfMaxOrder). Other integrators ignore it.
  int max_order_after_latch = kBdfMaxOrder;
};

}  // namespace unfurl::sim
