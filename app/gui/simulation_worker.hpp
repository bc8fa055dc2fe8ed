// The GUI's simulation thread. It owns the solver: the UI posts a request
// (a scene to run), the worker cancels the run in progress at its next step,
// starts the new one and appends every sample to a shared buffer as it is
// computed. The UI never waits on the solver: it copies what is new under a
// short lock, once per frame.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/body_solids.hpp"

namespace unfurl::app {

// What the UI sees of the current run.
struct RunProgress {
  long generation = 0;         // increments with every new run
  sim::RunStatus status = sim::RunStatus::finished;
  bool running = false;
  // Every sample is in: the curves are final while the summary (torque
  // margins, clearance) is still computed.
  bool integrated = false;
  std::string failure;         // a solver failure, said where
  double t_reached = 0;
  double wall_time_s = 0;
  long steps = 0;
  long rhs_calls = 0;
  // The finished (or failed) run's figures; null while it runs.
  std::shared_ptr<const sim::RunSummary> summary;
  std::optional<sim::ClosureTuning> closure;  // the last run's (a scene with loops)
};

class SimulationWorker {
 public:
  // on_change: called on the worker's thread when a run's samples are all
  // in and when it ends (the UI, which may be waiting, is woken by it).
  explicit SimulationWorker(std::function<void()> on_change = {});
  ~SimulationWorker();  // cancels the run and joins the thread
  SimulationWorker(const SimulationWorker&) = delete;
  SimulationWorker& operator=(const SimulationWorker&) = delete;

  // Cancels the run in progress (promptly: at its next step) and runs this
  // scene instead, its clearance measured between `solids` (none without
  // them). `failed_latches` name joints whose latch a study's failure took
  // out of the scene: the summary lists them as never latched. Returns the
  // new run's generation.
  long run(const sim::Scene& scene, studies::BodySolids solids = {}, std::vector<std::string> failed_latches = {});

  // Copies the samples and events the UI has not seen yet into `copy`
  // (which must hold the first copy.samples.size() samples of `generation`).
  // When a new run has started, `copy` moves to `previous` and starts
  // afresh. Returns the run's progress.
  RunProgress sync(long& generation, sim::Trajectory& copy, sim::Trajectory& previous);

 private:
  void loop();

  std::mutex mutex_;
  std::function<void()> on_change_;
  std::condition_variable wake_;
  std::optional<sim::Scene> pending_;  // the next run, taken by the worker
  studies::BodySolids pending_solids_;
  std::vector<std::string> pending_failed_latches_;
  bool quit_ = false;
  std::atomic<bool> cancel_{false};
  std::atomic<long> steps_live_{0}, rhs_live_{0};

  // Shared with the UI under mutex_.
  sim::Trajectory buffer_;
  RunProgress progress_;

  // Last: it starts running loop() at construction, so every member above
  // must already exist.
  std::thread thread_;
};

}  // namespace unfurl::app
