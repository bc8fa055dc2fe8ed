#include "unfurl/sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "dissipation_meter.hpp"
#include "latch_events.hpp"
#include "roundoff_guard.hpp"
#include "run_recording.hpp"

namespace unfurl::sim {

const char* run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::finished: return "finished";
    case RunStatus::failed: return "failed";
    case RunStatus::cancelled: return "cancelled";
  }
  return "?";
}

RunThreads default_run_threads() {
  return std::thread::hardware_concurrency() >= 2 ? RunThreads::two : RunThreads::one;
}

std::string describe(const Failure& f) {
  std::ostringstream s;
  s << f.check << " check failed at t = " << f.t << " s (step " << f.step << " s): " << f.reason;
  return s.str();
}

RunResult simulate(const Scene& scene, const RunSettings& settings, const RunObserver& observer, RunThreads threads) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunResult result;
  result.settings = settings;
  Dynamics dynamics(scene);
  Trajectory& trajectory = result.trajectory;
  trajectory.layout = dynamics.layout();
  if (const Regulator* regulator = dynamics.regulator()) {
    trajectory.loop_components = regulator->components();
    result.closure = ClosureTuning{dynamics.scales().length, dynamics.scales().rate, regulator->v_max(),
                                   !scene.regulator.v_max.has_value(), regulator->regularization(),
                                   !scene.regulator.regularization && scene.regulator.gains == GainTuning::full};
  }
  trajectory.load_columns = dynamics.load_columns();
  trajectory.sensor_columns = dynamics.sensor_columns();
  if (observer.on_start) observer.on_start(trajectory);

  const double t0 = 0.0;
  std::vector<double> y = dynamics.initial_state();
  // The guard's probe and the floor at the start are a report, not timed
  // with the run; the guard's looks during it are part of solving it, and are.
  const auto probe_start = std::chrono::steady_clock::now();
  RoundoffGuard guard(scene, settings.rtol, settings.atol);
  result.roundoff_floor = guard.floor_at_start(t0, y);
  const auto probe_time = std::chrono::steady_clock::now() - probe_start;
  std::vector<double> ys(y.size());
  RunRecording recording(dynamics, settings, observer, trajectory, threads);
  auto fail = [&](double t, double step, std::string check, std::string reason) {
    result.status = RunStatus::failed;
    result.failure = {t, step, std::move(check), std::move(reason)};
  };
  recording.sample(t0, y, 0.0, 0.0, 0.0);
  DissipationMeter dissipation(dynamics, t0);
  // A joint that starts exactly at its latch angle is caught from the start.
  for (int l = 0; l < dynamics.latch_count(); ++l)
    if (dynamics.latch_state().engaged(l)) recording.event({t0, l, dynamics.latches()[l]->joint});

  std::unique_ptr<Integrator> integrator;
  try {
    if (!recording.failed()) integrator = make_integrator(settings.integrator, dynamics, settings, t0, y);
  } catch (const std::exception& e) {
    fail(t0, 0, "integrator", e.what());
  }
  // From the first engaged latch on, one engaged at the start too: the
  // stability-limit detection's after_latch and the order's cap.
  auto apply_after_latch = [&] {
    if (dynamics.latch_state().engaged_count() == 0) return;
    if (settings.stability_limit_detection == StabilityLimitDetection::after_latch)
      integrator->watch_stability_limit();
    if (settings.max_order_after_latch < kBdfMaxOrder) integrator->limit_order(settings.max_order_after_latch);
  };
  if (integrator) apply_after_latch();
  LatchEvents events(dynamics, settings.event_window);
  long restarts = 0;
  if (result.status == RunStatus::finished) recording.step_end(t0, y, 0.0);
  recording.start_thread();

  long sample_index = 1;
  auto sample_time = [&](long k) { return std::min(t0 + k * settings.sample, settings.t_end); };
  double t = t0;
  while (integrator && result.status == RunStatus::finished && !recording.failed() && t < settings.t_end) {
    if (observer.cancel && observer.cancel->load()) {
      result.status = RunStatus::cancelled;
      break;
    }
    const StepOutcome step = integrator->step(settings.t_end);
    if (step.status == StepStatus::failed) {
      fail(step.t, integrator->current_step(), "integrator", step.reason);
      break;
    }
    recording.step_taken(integrator->last_step());
    const LatchGroup group = events.find(*integrator, step);
    const double t_done = group.empty() ? step.t : group.t_restart;
    // Samples up to where this step is done, by the method's interpolant.
    while (sample_index >= 0 && sample_time(sample_index) <= t_done) {
      integrator->interpolate(sample_time(sample_index), ys.data());
      dissipation.advance(*integrator, sample_time(sample_index));
      recording.sample(sample_time(sample_index), ys, dissipation.work(), dissipation.drive_work(),
                       integrator->current_step());
      sample_index = sample_time(sample_index) >= settings.t_end ? -1 : sample_index + 1;
    }
    if (recording.failed()) break;
    integrator->interpolate(t_done, y.data());
    dissipation.advance(*integrator, t_done);
    if (!group.empty()) {
      events.engage(group, *integrator, y.data());
      std::vector<LatchRoot> roots = group.roots;
      std::stable_sort(roots.begin(), roots.end(), [](const LatchRoot& a, const LatchRoot& b) { return a.t < b.t; });
      for (const LatchRoot& r : group.roots) recording.engage(r.latch);
      for (const LatchRoot& r : roots) recording.event({r.t, r.latch, dynamics.latches()[r.latch]->joint});
      integrator->restart(t_done, y.data());
      apply_after_latch();
      recording.restarted();
      recording.latched();
      ++restarts;
    }
    t = t_done;
    if (settings.roundoff_guard && t < settings.t_end && guard.step_taken(t, y, dynamics, *integrator)) {
      integrator->restart(t, y.data());
      recording.restarted();
    }
    recording.step_end(t, y, integrator->current_step());
    if (recording.failed()) break;
    if (t < settings.t_end && settings.max_wall_time > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count() > settings.max_wall_time) {
      std::ostringstream why;
      why << "over the time budget of " << settings.max_wall_time << " s of wall time (" << integrator->stats().steps
          << " steps)";
      fail(t, integrator->current_step(), "time budget", why.str());
      break;
    }
    if (integrator->stats().steps > settings.max_steps) {
      fail(t, integrator->current_step(), "steps", "more than " + std::to_string(settings.max_steps) + " steps");
      break;
    }
    if (observer.on_progress)
      observer.on_progress({t, integrator->current_step(), integrator->stats().steps, dynamics.rhs_calls()});
  }
  // A check of the recording's failed at a step the integrator had passed:
  // the run ends there.
  if (const std::optional<Failure> failure = recording.finish()) {
    result.status = RunStatus::failed;
    result.failure = *failure;
  }

  if (integrator) result.stats = integrator->stats();
  result.stats.restarts = restarts;
  result.stats.min_step = recording.monitor().min_step();
  result.stats.min_step_after_restart = recording.monitor().min_step_after_restart();
  result.stats.grazes = events.grazes();
  result.peaks = recording.monitor().peaks(result.status != RunStatus::failed);
  result.rhs_calls = dynamics.rhs_calls();
  result.jacobian_product_evals = dynamics.jacobian_product_evals();
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start - probe_time).count();
  // With the latches as they ended.
  if (result.status != RunStatus::failed) result.roundoff_floor_end = guard.floor_at(t, y, dynamics);
  result.tolerance_raises = guard.raises();
  return result;
}

}  // namespace unfurl::sim
