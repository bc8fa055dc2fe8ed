#include "simulation_worker.hpp"

#include <chrono>

#include "unfurl/studies/clearance.hpp"

namespace unfurl::app {

SimulationWorker::SimulationWorker(std::function<void()> on_change)
    : on_change_(std::move(on_change)), thread_([this] { loop(); }) {}

SimulationWorker::~SimulationWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

long SimulationWorker::run(const sim::Scene& scene, studies::BodySolids solids, std::vector<std::string> failed_latches) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_ = scene;
  pending_solids_ = std::move(solids);
  pending_failed_latches_ = std::move(failed_latches);
  cancel_ = true;
  wake_.notify_one();
  // The generation the request will run as: the worker takes requests in
  // order and increments once per run it starts.
  return progress_.generation + 1;
}

RunProgress SimulationWorker::sync(long& generation, sim::Trajectory& copy, sim::Trajectory& previous) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != progress_.generation) {
    generation = progress_.generation;
    if (!copy.empty()) previous = std::move(copy);
    copy = sim::Trajectory{};
  }
  copy.layout = buffer_.layout;
  // The run's column names, once (they are set before its first sample).
  if (copy.load_columns.size() != buffer_.load_columns.size()) copy.load_columns = buffer_.load_columns;
  if (copy.sensor_columns.size() != buffer_.sensor_columns.size()) copy.sensor_columns = buffer_.sensor_columns;
  if (copy.loop_components.size() != buffer_.loop_components.size()) copy.loop_components = buffer_.loop_components;
  copy.samples.insert(copy.samples.end(), buffer_.samples.begin() + static_cast<long>(copy.samples.size()),
                      buffer_.samples.end());
  copy.events.insert(copy.events.end(), buffer_.events.begin() + static_cast<long>(copy.events.size()),
                     buffer_.events.end());
  RunProgress p = progress_;
  if (p.running) {
    p.steps = steps_live_.load(std::memory_order_relaxed);
    p.rhs_calls = rhs_live_.load(std::memory_order_relaxed);
  }
  return p;
}

void SimulationWorker::loop() {
  // The solver runs at the UI's priority. Lowered (nice 19) it got what the
  // UI and the software renderer's threads left on two cores: the
  // pantograph's re-run took 0.52-0.59 s against 0.21 s in `unfurl
  // simulate`; at equal priority 0.27-0.29 s, with the UI at 33-35 frames/s
  // instead of 41-43 while it computes.
  for (;;) {
    sim::Scene scene;
    studies::BodySolids solids;
    std::vector<std::string> failed_latches;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      scene = std::move(*pending_);
      solids = std::move(pending_solids_);
      failed_latches = std::move(pending_failed_latches_);
      pending_.reset();
      cancel_ = false;
      buffer_ = sim::Trajectory{};
      const long generation = progress_.generation + 1;
      progress_ = RunProgress{};
      progress_.generation = generation;
      progress_.running = true;
    }
    const auto start = std::chrono::steady_clock::now();
    sim::RunObserver observer;
    observer.cancel = &cancel_;
    observer.on_start = [&](const sim::Trajectory& header) {
      std::lock_guard<std::mutex> lock(mutex_);
      buffer_ = header;
    };
    observer.on_sample = [&](const sim::Sample& s) {
      std::lock_guard<std::mutex> lock(mutex_);
      buffer_.samples.push_back(s);
      progress_.t_reached = s.t;
      progress_.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    observer.on_progress = [&](const sim::StepProgress& p) {
      // Atomics rather than the lock: the status line reads them every frame.
      steps_live_.store(p.steps, std::memory_order_relaxed);
      rhs_live_.store(p.rhs_calls, std::memory_order_relaxed);
    };
    observer.on_event = [&](const sim::LatchEvent& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      buffer_.events.push_back(e);
    };
    sim::RunResult result;
    try {
      result = sim::simulate(scene, scene.run, observer);
    } catch (const std::exception& e) {
      result.status = sim::RunStatus::failed;
      result.failure = {0, 0, "setup", e.what()};
    }
    if (result.status != sim::RunStatus::cancelled) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_.integrated = true;
      }
      if (on_change_) on_change_();
    }
    // An edit during the summary (a large array's torque margins and
    // clearance take seconds) cancels it too: its run is superseded.
    std::shared_ptr<const sim::RunSummary> summary;
    if (result.status != sim::RunStatus::cancelled) {
      sim::RunSummary s = sim::summarize(scene, result, &cancel_);
      if (solids.bodies.size() == static_cast<std::size_t>(scene.model.size()))
        s.clearance = studies::check_clearance(scene, solids, result.trajectory, &cancel_);
      s.unlatched.insert(s.unlatched.end(), failed_latches.begin(), failed_latches.end());
      if (cancel_)
        result.status = sim::RunStatus::cancelled;
      else
        summary = std::make_shared<const sim::RunSummary>(std::move(s));
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      progress_.summary = std::move(summary);
      progress_.closure = result.closure;
      buffer_.layout = result.trajectory.layout;
      progress_.running = false;
      progress_.status = result.status;
      progress_.failure = result.status == sim::RunStatus::failed ? sim::describe(result.failure) : "";
      progress_.steps = result.stats.steps;
      progress_.rhs_calls = result.rhs_calls;
      progress_.wall_time_s = result.wall_time_s;
    }
    if (on_change_) on_change_();
  }
}

}  // namespace unfurl::app
