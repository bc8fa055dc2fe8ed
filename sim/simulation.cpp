#include "simulation.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace unfurl {

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

  void record(double t, const std::vector<double>& y) {
    dynamics_.observe(t, y.data(), observation_);
    Sample s;
    s.t = t;
    s.y = y;
    s.dq = observation_.dq;
    s.closure = observation_.closure;
    s.energy = observation_.energy;
    trajectory_.samples.push_back(std::move(s));
    if (observer_.on_sample) observer_.on_sample(trajectory_.samples.back());
  }

  const Observation& last() const { return observation_; }

 private:
  Dynamics& dynamics_;
  const RunObserver& observer_;
  Trajectory& trajectory_;
  Observation observation_;
};

double largest_closure(const Observation& o) {
  double worst = 0;
  for (const ClosureError& c : o.closure) worst = std::max({worst, c.distance, c.angle});
  return worst;
}

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

  std::vector<double> y = dynamics.initial_state();
  std::vector<double> ys(y.size());
  Recorder recorder(dynamics, observer, trajectory);
  const double t0 = 0.0;
  recorder.record(t0, y);
  // A joint that starts exactly at its latch angle is caught from the start.
  for (int l = 0; l < dynamics.latch_count(); ++l) {
    if (!dynamics.latch_state().engaged(l)) continue;
    const LatchEvent event{t0, l, scene.latches[l].joint};
    trajectory.events.push_back(event);
    if (observer.on_event) observer.on_event(event);
  }

  auto fail = [&](double t, double step, std::string check, std::string reason) {
    result.status = RunStatus::failed;
    result.failure = {t, step, std::move(check), std::move(reason)};
  };

  std::unique_ptr<Integrator> integrator;
  try {
    integrator = make_integrator(settings.integrator, dynamics, settings, t0, y);
  } catch (const std::exception& e) {
    fail(t0, 0, "integrator", e.what());
  }

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
    // Samples inside the step just taken, by the method's interpolant.
    while (sample_index >= 0 && sample_time(sample_index) <= step.t) {
      integrator->interpolate(sample_time(sample_index), ys.data());
      recorder.record(sample_time(sample_index), ys);
      if (largest_closure(recorder.last()) > settings.max_closure) {
        std::ostringstream why;
        why << "a loop opened by " << largest_closure(recorder.last()) << " (limit " << settings.max_closure
            << "): the regulator lost the loop";
        fail(sample_time(sample_index), integrator->current_step(), "closure", why.str());
        break;
      }
      sample_index = sample_time(sample_index) >= settings.t_end ? -1 : sample_index + 1;
    }
    if (result.status != RunStatus::finished) break;
    t = step.t;
    if (step.status == StepStatus::root) {
      integrator->interpolate(t, y.data());
      std::vector<double> s(dynamics.latch_count());
      dynamics.switching_functions(y.data(), s.data());
      for (int l : integrator->roots()) s[l] = 0;
      for (int l = 0; l < dynamics.latch_count(); ++l) {
        if (dynamics.latch_state().engaged(l) || s[l] > 0) continue;
        dynamics.latch_state().engage(l);
        const LatchEvent event{t, l, scene.latches[l].joint};
        trajectory.events.push_back(event);
        if (observer.on_event) observer.on_event(event);
      }
      integrator->restart(t, y.data());
    }
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
  result.rhs_calls = dynamics.rhs_calls();
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace unfurl
