// The simulation thread and the UI's hand-over: samples stream to a reader
// polling from another thread, a new request cancels the run in progress,
// and the worker shuts down while running. Built twice: plainly and with
// ThreadSanitizer (test_handover_tsan).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "simulation_worker.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

using app::RunProgress;
using app::SimulationWorker;

// Polls like the UI's frame loop until the run of `generation` finished.
RunProgress poll_until_done(SimulationWorker& worker, long generation, long& seen, sim::Trajectory& copy,
                            sim::Trajectory& previous) {
  for (int frame = 0; frame < 60 * 120; ++frame) {
    const RunProgress p = worker.sync(seen, copy, previous);
    for (std::size_t k = 1; k < copy.samples.size(); ++k) EXPECT_GT(copy.samples[k].t, copy.samples[k - 1].t);
    if (seen == generation && !p.running) return p;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ADD_FAILURE() << "the run did not finish";
  return {};
}

TEST(Handover, SamplesStreamToTheReader) {
  SimulationWorker worker;
  const sim::Scene scene = test::scene_file("fourbar", {{"run.t_end", "1"}});
  const long generation = worker.run(scene);
  long seen = -1;
  sim::Trajectory copy, previous;
  const RunProgress p = poll_until_done(worker, generation, seen, copy, previous);
  EXPECT_EQ(p.status, sim::RunStatus::finished);
  EXPECT_EQ(copy.samples.size(), 101u);
  EXPECT_DOUBLE_EQ(copy.t_end(), 1.0);
  EXPECT_GT(p.steps, 0);
  // The copy is the run: the same states as a direct simulation.
  const sim::RunResult direct = sim::simulate(scene, scene.run);
  ASSERT_EQ(direct.trajectory.samples.size(), copy.samples.size());
  EXPECT_EQ(direct.trajectory.samples.back().y, copy.samples.back().y);
}

TEST(Handover, AnIntegratedRunHasAllItsSamplesBeforeItsSummary) {
  // The plots draw a run's final curves once it is integrated, while its
  // summary (torque margins, clearance) is still being computed.
  SimulationWorker worker;
  const long generation = worker.run(test::scene_file("pantograph", {{"run.t_end", "2"}}));
  long seen = -1;
  sim::Trajectory copy, previous;
  RunProgress p;
  for (int frame = 0; frame < 60 * 120 && !(seen == generation && !p.running); ++frame) {
    p = worker.sync(seen, copy, previous);
    if (seen == generation && p.integrated) {
      EXPECT_EQ(copy.samples.size(), 201u);
      EXPECT_DOUBLE_EQ(copy.t_end(), 2.0);
    }
    if (seen == generation && !p.integrated) {
      EXPECT_TRUE(p.running);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_TRUE(p.integrated);
  EXPECT_FALSE(p.running);
  EXPECT_NE(p.summary, nullptr);
}

TEST(Handover, TheWorkerCallsBackWhenTheCurvesAreFinalAndWhenTheRunEnds) {
  // The workbench waits for input between frames while a run computes: these
  // calls wake it.
  std::mutex m;
  std::condition_variable called;
  std::vector<RunProgress> at_call;
  std::vector<std::size_t> samples_at_call;
  std::atomic<SimulationWorker*> self{nullptr};
  SimulationWorker worker([&] {
    long generation = -1;
    sim::Trajectory copy, previous;
    const RunProgress p = self.load()->sync(generation, copy, previous);
    std::lock_guard<std::mutex> lock(m);
    at_call.push_back(p);
    samples_at_call.push_back(copy.samples.size());
    called.notify_one();
  });
  self = &worker;
  worker.run(test::scene_file("pantograph", {{"run.t_end", "2"}}));
  std::unique_lock<std::mutex> lock(m);
  ASSERT_TRUE(called.wait_for(lock, std::chrono::minutes(2), [&] { return at_call.size() >= 2; }));
  EXPECT_TRUE(at_call[0].integrated);
  EXPECT_EQ(samples_at_call[0], 201u);
  EXPECT_FALSE(at_call[1].running);
  EXPECT_NE(at_call[1].summary, nullptr);
}

TEST(Handover, ANewRequestCancelsTheRunInProgress) {
  SimulationWorker worker;
  long seen = -1;
  sim::Trajectory copy, previous;
  // A long run, superseded once it has produced something.
  const long first = worker.run(test::scene_file("pantograph", {{"run.t_end", "1000"}}));
  while (seen != first || copy.samples.size() < 20) {
    worker.sync(seen, copy, previous);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto asked = std::chrono::steady_clock::now();
  const long second = worker.run(test::scene_file("zfold", {{"run.t_end", "0.5"}}));
  EXPECT_EQ(second, first + 1);
  const RunProgress p = poll_until_done(worker, second, seen, copy, previous);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  EXPECT_LT(seconds, 30.0) << "the cancelled run did not stop";
  EXPECT_EQ(p.status, sim::RunStatus::finished);
  EXPECT_EQ(copy.samples.size(), 51u);
  // The cancelled run's samples moved to `previous`, cut short.
  EXPECT_GE(previous.samples.size(), 20u);
  EXPECT_LT(previous.t_end(), 1000.0);
}

TEST(Handover, RapidRequestsEndWithTheLastOne) {
  SimulationWorker worker;
  long seen = -1, last = 0;
  sim::Trajectory copy, previous;
  for (int k = 0; k < 20; ++k) {
    last = worker.run(test::scene_file("zfold", {{"run.t_end", std::to_string(0.1 + 0.01 * k)}}));
    worker.sync(seen, copy, previous);
  }
  poll_until_done(worker, last, seen, copy, previous);
  EXPECT_NEAR(copy.t_end(), 0.29, 1e-12);
}

TEST(Handover, ShutsDownWhileRunning) {
  auto worker = std::make_unique<SimulationWorker>();
  worker->run(test::scene_file("pantograph", {{"run.t_end", "1000"}}));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  worker.reset();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

}  // namespace
}  // namespace unfurl
