// A run whose loads, peaks and samples are recorded beside the integrator
// (RunThreads::two, run_recording.hpp) is the same run as on one thread, to
// the last bit, and a check that fails on the recording's thread ends it
// where one thread ends it. Built twice: plainly and with ThreadSanitizer
// (test_handover_tsan).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

void expect_same_peak(const sim::Peak& a, const sim::Peak& b, const std::string& what) {
  EXPECT_EQ(a.value, b.value) << what;
  EXPECT_EQ(std::isnan(a.t), std::isnan(b.t)) << what;
  if (!std::isnan(a.t)) {
    EXPECT_EQ(a.t, b.t) << what;
  }
}

void expect_same_peaks(const std::vector<sim::Peak>& a, const std::vector<sim::Peak>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) expect_same_peak(a[k], b[k], what + " " + std::to_string(k));
}

void expect_same_run(const sim::RunResult& one, const sim::RunResult& two) {
  EXPECT_EQ(one.status, two.status);
  EXPECT_EQ(one.failure.t, two.failure.t);
  EXPECT_EQ(one.failure.step, two.failure.step);
  EXPECT_EQ(one.failure.check, two.failure.check);
  EXPECT_EQ(one.failure.reason, two.failure.reason);
  const auto &a = one.trajectory, &b = two.trajectory;
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    const sim::Sample &s = a.samples[k], &r = b.samples[k];
    ASSERT_EQ(s.t, r.t) << k;
    EXPECT_EQ(s.y, r.y) << "sample " << k;
    EXPECT_EQ(s.q_dot, r.q_dot) << "sample " << k;
    EXPECT_EQ(s.loads.element, r.loads.element) << "sample " << k;
    EXPECT_EQ(s.loads.loop_force, r.loads.loop_force) << "sample " << k;
    EXPECT_EQ(s.loads.determinacy, r.loads.determinacy) << "sample " << k;
    ASSERT_EQ(s.loads.reaction.size(), r.loads.reaction.size());
    for (std::size_t j = 0; j < s.loads.reaction.size(); ++j)
      EXPECT_EQ(s.loads.reaction[j], r.loads.reaction[j]) << "sample " << k << " joint " << j;
    EXPECT_EQ(s.energy.kinetic, r.energy.kinetic) << "sample " << k;
    EXPECT_EQ(s.energy.dissipated, r.energy.dissipated) << "sample " << k;
  }
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    EXPECT_EQ(a.events[k].t, b.events[k].t);
    EXPECT_EQ(a.events[k].latch, b.events[k].latch);
  }
  const sim::RunPeaks &p = one.peaks, &q = two.peaks;
  expect_same_peaks(p.latch_torque, q.latch_torque, "latch torque");
  expect_same_peaks(p.hinge_force, q.hinge_force, "hinge force");
  expect_same_peaks(p.hinge_moment, q.hinge_moment, "hinge moment");
  expect_same_peaks(p.hinge_force_indeterminate, q.hinge_force_indeterminate, "indeterminate hinge force");
  EXPECT_EQ(p.indeterminate_spans, q.indeterminate_spans);
  EXPECT_EQ(p.lowest_closure_rank, q.lowest_closure_rank);
  expect_same_peak(p.gap_m, q.gap_m, "gap");
  expect_same_peak(p.gap_rad_before_latch, q.gap_rad_before_latch, "angular gap before the latches");
  EXPECT_EQ(one.stats.min_step, two.stats.min_step);
  EXPECT_EQ(one.stats.min_step_after_restart, two.stats.min_step_after_restart);
}

TEST(RunThreads, TwoThreadsRecordTheSameRunAsOne) {
  // The whole deployment: its latch-up, where the loads pass the deployed
  // branch point and the monitor remembers how (closure_rank.hpp), and the
  // loads after it, which depend on that memory.
  const sim::Scene scene = test::scene_file("pantograph");
  const sim::RunResult one = sim::simulate(scene, scene.run, {}, sim::RunThreads::one);
  const sim::RunResult two = sim::simulate(scene, scene.run, {}, sim::RunThreads::two);
  ASSERT_EQ(one.status, sim::RunStatus::finished) << sim::describe(one.failure);
  EXPECT_EQ(one.trajectory.events.size(), 8u);
  EXPECT_EQ(one.stats.steps, two.stats.steps);
  EXPECT_EQ(one.rhs_calls, two.rhs_calls);
  expect_same_run(one, two);
}

TEST(RunThreads, ACheckThatFailsBesideTheIntegratorEndsTheRunWhereOneThreadEndsIt) {
  // A closure limit the regulator cannot hold (its gap after the latch-up
  // is about 1e-10): the check fails on the recording's thread, some steps
  // behind the integrator, and the run keeps what it had at that step (the
  // integrator's counts include the steps it took past it).
  const sim::Scene scene = test::scene_file("pantograph", {{"run.max_closure", "1e-11"}});
  const sim::RunResult one = sim::simulate(scene, scene.run, {}, sim::RunThreads::one);
  const sim::RunResult two = sim::simulate(scene, scene.run, {}, sim::RunThreads::two);
  ASSERT_EQ(one.status, sim::RunStatus::failed);
  EXPECT_EQ(one.failure.check, "closure");
  EXPECT_GT(one.failure.t, 7.0);  // at the latch-up
  EXPECT_LT(one.trajectory.samples.back().t, 20.0);
  expect_same_run(one, two);
}

}  // namespace
}  // namespace unfurl
