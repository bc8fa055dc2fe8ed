// Runs a scene from its initial state to t_end: steps the chosen integrator,
// samples the state at fixed times by the integrator's interpolation,
// engages latches at the roots it finds (and restarts the integrator), and
// stops with what it computed so far on a failure or a cancel.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include "unfurl/sim/integrator.hpp"
#include "unfurl/sim/loads.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/tolerance_raise.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::sim {

enum class RunStatus { finished, failed, cancelled };

// Where and why a run stopped early.
struct Failure {
  double t = 0;
  double step = 0;
  std::string check;   // which check failed: "integrator", "closure", ...
  std::string reason;
};

// "closure check failed at t = 3.2 s (step 1e-5 s): ..."
std::string describe(const Failure& failure);

// How a run's loops were closed: the mechanism's scales the closure is
// measured against and the regulator's tuning they gave.
struct ClosureTuning {
  double length = 0;          // m (MechanismScales)
  double rate = 0;            // rad/s, the mechanism's fastest own rate
  double v_max = 0;           // rad/s, the bandwidth in use
  bool v_max_automatic = true;  // chosen from `rate`, not set by the scene
  double regularization = 0;  // dimensionless: delta over W's largest eigenvalue at the start
  bool regularization_automatic = true;  // chosen from W's weakest mode, not set by the scene
};

struct RunResult {
  RunStatus status = RunStatus::finished;
  Failure failure;
  SolverStats stats;
  RunPeaks peaks;  // over every step, not only the samples
  long rhs_calls = 0;
  long jacobian_product_evals = 0;  // Dynamics::jacobian_times' evaluations, held gains
  double wall_time_s = 0;
  // f's round-off at the start and at the end (roundoff_floor.hpp):
  // tolerances below it cost steps and buy no accuracy. A latched
  // mechanism at its branch point has more (the closure's near-null
  // directions amplify it; pantograph: 1.8e-11 at the start, 1.4e-10 latched).
  double roundoff_floor = 0;
  double roundoff_floor_end = 0;
  // Where the tolerances were raised to the floor (roundoff_guard.hpp), in order;
  // settings keeps the tolerances asked for.
  std::vector<ToleranceRaise> tolerance_raises;
  RunSettings settings;
  std::optional<ClosureTuning> closure;  // a scene with loops
  Trajectory trajectory;
};

// Where a run is, after each step.
struct StepProgress {
  double t = 0;
  double step = 0;
  long steps = 0;
  long rhs_calls = 0;
};

// Hooks for a caller that watches or stops a run (a GUI's thread, a
// progress bar). on_start, on_progress and cancel are called or read on the
// running thread; on_sample and on_event on the thread that records the run
// (the running thread's or, with RunThreads::two, one beside it), in the
// run's order.
struct RunObserver {
  // Before the first sample: the trajectory as yet without samples (its
  // layout and the names of its load, sensor and loop columns).
  std::function<void(const Trajectory&)> on_start;
  std::function<void(const Sample&)> on_sample;
  std::function<void(const LatchEvent&)> on_event;
  std::function<void(const StepProgress&)> on_progress;  // after every step
  const std::atomic<bool>* cancel = nullptr;
};

// How many threads a run takes: with two, the loads, peaks and samples are
// computed beside the integrator (run_recording.hpp), with the same results.
// Callers that run several cases at once on every core take one.
enum class RunThreads { one, two };
// Two where the machine has two cores or more.
RunThreads default_run_threads();

RunResult simulate(const Scene& scene, const RunSettings& settings, const RunObserver& observer = {},
                   RunThreads threads = default_run_threads());

const char* run_status_name(RunStatus status);

}  // namespace unfurl::sim
