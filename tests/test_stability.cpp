// The stability suite's small cases: each finishes, or fails the check it
// is expected to fail with a message saying where; the singular starts
// report what they did; the time budget stops a run cleanly.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/studies/gain_study.hpp"
#include "unfurl/studies/stability_results.hpp"
#include "unfurl/studies/stability_verdicts.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {

// How gtest names a case in its output.
void PrintTo(const studies::StabilityCase& c, std::ostream* os) { *os << c.group << " / " << c.label; }

namespace {

std::vector<studies::StabilityCase> small_cases() {
  std::vector<studies::StabilityCase> out;
  for (const studies::StabilityCase& c : studies::stability_cases(120))
    if (c.small) out.push_back(c);
  return out;
}

class SmallCase : public ::testing::TestWithParam<studies::StabilityCase> {};

TEST_P(SmallCase, EndsAsExpected) {
  const studies::StabilityResult r = studies::run_stability_case(GetParam());
  EXPECT_TRUE(studies::as_expected(r)) << r.spec.group << " / " << r.spec.label << ": "
                                       << (r.status == sim::RunStatus::finished ? "finished" : r.failure);
  if (r.status == sim::RunStatus::failed) {
    // Where and why: the time, the step and the check.
    EXPECT_NE(r.failure.find("check failed at t = "), std::string::npos) << r.failure;
    EXPECT_NE(r.failure.find("(step "), std::string::npos) << r.failure;
  }
  EXPECT_TRUE(std::isfinite(r.energy_final)) << "a result written as NaN";
  EXPECT_GT(r.steps, 0);
}

INSTANTIATE_TEST_SUITE_P(Stiff, SmallCase, ::testing::ValuesIn(small_cases()),
                         [](const ::testing::TestParamInfo<studies::StabilityCase>& info) {
                           std::string name = std::to_string(info.index) + "_" + info.param.label;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

const studies::StabilityCase& case_labelled(const std::vector<studies::StabilityCase>& cases,
                                            const std::string& label) {
  for (const studies::StabilityCase& c : cases)
    if (c.label == label) return c;
  throw std::runtime_error("no case " + label);
}

TEST(SingularStart, ExactStowedStateReportsTheBranchOfEachLoop) {
  const auto cases = studies::stability_cases(120);
  const studies::StabilityResult r = studies::run_stability_case(case_labelled(cases, "exact stowed state (a = pi/2)"));
  ASSERT_EQ(r.status, sim::RunStatus::finished) << r.failure;
  ASSERT_EQ(r.notes.size(), 3u);
  // The run opened the frames and the outer panel pair; panels 1 and 2 of
  // each chain stayed folded, so their latches did not engage.
  EXPECT_EQ(r.notes[0], "loop A1: held j2, j6; opened j1, j5, j9");
  EXPECT_EQ(r.latches_engaged, 4);
  EXPECT_LT(r.max_closure_gap, 1e-6);
}

TEST(SingularStart, DeployedStateIsLatchedFromTheStartAndStays) {
  const auto cases = studies::stability_cases(120);
  const studies::StabilityResult r = studies::run_stability_case(case_labelled(cases, "fully deployed state (q = 0)"));
  ASSERT_EQ(r.status, sim::RunStatus::finished) << r.failure;
  EXPECT_EQ(r.latches_engaged, 8);
  for (const std::string& note : r.notes) EXPECT_NE(note.find("opened none"), std::string::npos) << note;
  EXPECT_LT(r.max_closure_gap, 1e-6);
}

TEST(SingularStart, OpenLoopIsPulledShut) {
  const sim::Scene scene = sim::load_builtin_scene("pantograph", {{"closure_tolerance", "0.01"},
                                                                  {"initial.q.j9", "3.122592653589793"},
                                                                  {"run.t_end", "0.05"},
                                                                  {"run.sample", "1e-4"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  auto largest_gap = [](const sim::Sample& s) {
    double gap = 0;
    for (const sim::ClosureError& c : s.closure) gap = std::max({gap, c.distance, c.angle});
    return gap;
  };
  const double start = largest_gap(run.trajectory.samples.front());
  EXPECT_GT(start, 5e-4);
  // The slowest designed pole is b0 = p0 v_max = 2000 1/s: a thousandfold
  // reduction takes about 7 / 2000 s.
  double at_10ms = 0;
  for (const sim::Sample& s : run.trajectory.samples)
    if (std::abs(s.t - 0.01) < 1e-9)
      at_10ms = std::max(at_10ms, largest_gap(s));
  EXPECT_LT(at_10ms, 1e-3 * start);
}

TEST(TimeBudget, StopsARunCleanlyAndKeepsWhatItComputed) {
  const sim::Scene scene =
      sim::load_builtin_scene("pantograph", {{"run.max_wall_time", "0.02"}, {"run.integrator", "rk4"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::failed);
  EXPECT_EQ(run.failure.check, "time budget");
  EXPECT_GE(run.trajectory.samples.size(), 1u);
  EXPECT_LT(run.trajectory.t_end(), scene.run.t_end);
}

}  // namespace
}  // namespace unfurl
