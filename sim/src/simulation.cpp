#include "unfurl/sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "dissipation_meter.hpp"
#include "latch_events.hpp"
#include "roundoff_guard.hpp"
#include "run_monitor.hpp"

namespace unfurl::sim {

const char* run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::finished: return "finished";
    case RunStatus::failed: return "failed";
    case RunStatus::cancelled: return "cancelled";
  }
  return "?";
}

namespace {

class Recorder {
 public:
  Recorder(Dynamics& dynamics, const RunObserver& observer, Trajectory& trajectory)
      : dynamics_(dynamics), observer_(observer), trajectory_(trajectory) {}

  // False where the state cannot be evaluated (nothing is recorded).
  bool record(double t, const std::vector<double>& y, double dissipated, double driven) {
    if (!dynamics_.observe(t, y.data(), observation_)) return false;
    observation_.energy.dissipated = dissipated;
    observation_.energy.driven = driven;
    Sample s;
    s.t = t;
    s.y = y;
    s.q_dot = observation_.q_dot;
    s.closure = observation_.closure;
    s.energy = observation_.energy;
    s.momentum = observation_.momentum;
    s.loads = observation_.loads;
    trajectory_.samples.push_back(std::move(s));
    if (observer_.on_sample) observer_.on_sample(trajectory_.samples.back());
    return true;
  }

  void event(const LatchEvent& e) {
    trajectory_.events.push_back(e);
    if (observer_.on_event) observer_.on_event(e);
  }

 private:
  Dynamics& dynamics_;
  const RunObserver& observer_;
  Trajectory& trajectory_;
  Observation observation_;
};

}  // namespace

std::string describe(const Failure& f) {
  std::ostringstream s;
  s << f.check << " check failed at t = " << f.t << " s (step " << f.step << " s): " << f.reason;
  return s.str();
}

RunResult simulate(const Scene& scene, const RunSettings& settings, const RunObserver& observer) {
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
  Recorder recorder(dynamics, observer, trajectory);
  auto fail = [&](double t, double step, std::string check, std::string reason) {
    result.status = RunStatus::failed;
    result.failure = {t, step, std::move(check), std::move(reason)};
  };
  const char* kNotFinite = "the equations of motion have no finite value here (or the loop-closure system is singular)";
  if (!recorder.record(t0, y, 0.0, 0.0)) fail(t0, 0, "evaluation", kNotFinite);
  DissipationMeter dissipation(dynamics, t0);
  // A joint that starts exactly at its latch angle is caught from the start.
  for (int l = 0; l < dynamics.latch_count(); ++l)
    if (dynamics.latch_state().engaged(l)) recorder.event({t0, l, dynamics.latches()[l]->joint});

  std::unique_ptr<Integrator> integrator;
  try {
    if (result.status == RunStatus::finished)
      integrator = make_integrator(settings.integrator, dynamics, settings, t0, y);
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
  RunMonitor monitor(dynamics);
  long restarts = 0;
  // The loads and the gap are checked at every step's end, the start included.
  auto check_step_end = [&](double t) {
    const double step = integrator ? integrator->current_step() : 0.0;
    const std::optional<double> gap = monitor.observe(t, y.data());
    if (!gap) {
      fail(t, step, "evaluation", kNotFinite);
      return false;
    }
    if (*gap <= settings.max_closure) return true;
    std::ostringstream why;
    why << "a loop opened by " << *gap << " (rad, or length over the mechanism's " << dynamics.scales().length
        << " m; limit " << settings.max_closure << "): the regulator lost the loop";
    fail(t, step, "closure", why.str());
    return false;
  };
  if (result.status == RunStatus::finished) check_step_end(t0);

  long sample_index = 1;
  auto sample_time = [&](long k) { return std::min(t0 + k * settings.sample, settings.t_end); };
  double t = t0;
  while (integrator && result.status == RunStatus::finished && t < settings.t_end) {
    if (observer.cancel && observer.cancel->load()) {
      result.status = RunStatus::cancelled;
      break;
    }
    const StepOutcome step = integrator->step(settings.t_end);
    if (step.status == StepStatus::failed) {
      fail(step.t, integrator->current_step(), "integrator", step.reason);
      break;
    }
    monitor.step_taken(integrator->last_step());
    const LatchGroup group = events.find(*integrator, step);
    const double t_done = group.empty() ? step.t : group.t_restart;
    // Samples up to where this step is done, by the method's interpolant.
    while (sample_index >= 0 && sample_time(sample_index) <= t_done) {
      integrator->interpolate(sample_time(sample_index), ys.data());
      dissipation.advance(*integrator, sample_time(sample_index));
      if (!recorder.record(sample_time(sample_index), ys, dissipation.work(), dissipation.drive_work())) {
        fail(sample_time(sample_index), integrator->current_step(), "evaluation", kNotFinite);
        break;
      }
      sample_index = sample_time(sample_index) >= settings.t_end ? -1 : sample_index + 1;
    }
    if (result.status != RunStatus::finished) break;
    integrator->interpolate(t_done, y.data());
    dissipation.advance(*integrator, t_done);
    if (!group.empty()) {
      events.engage(group, *integrator, y.data());
      std::vector<LatchRoot> roots = group.roots;
      std::stable_sort(roots.begin(), roots.end(), [](const LatchRoot& a, const LatchRoot& b) { return a.t < b.t; });
      for (const LatchRoot& r : roots) recorder.event({r.t, r.latch, dynamics.latches()[r.latch]->joint});
      integrator->restart(t_done, y.data());
      apply_after_latch();
      monitor.restarted();
      monitor.latched();
      ++restarts;
    }
    t = t_done;
    if (settings.roundoff_guard && t < settings.t_end && guard.step_taken(t, y, dynamics, *integrator)) {
      integrator->restart(t, y.data());
      monitor.restarted();
    }
    if (!check_step_end(t)) break;
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

  if (integrator) result.stats = integrator->stats();
  result.stats.restarts = restarts;
  result.stats.min_step = monitor.min_step();
  result.stats.min_step_after_restart = monitor.min_step_after_restart();
  result.stats.grazes = events.grazes();
  result.peaks = monitor.peaks(result.status != RunStatus::failed);
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
