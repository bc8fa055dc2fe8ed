// Loads where rigid mechanics determines them, and where it does not: the
// pantograph's loops are redundant at its deployed branch point, so the
// hinge forces inside them are indeterminate at and after the latch-up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "support.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

// Through the latch-up at 7.39 s unless told.
sim::RunSummary run_pantograph(std::vector<sim::Override> overrides, const std::string& t_end = "7.6") {
  overrides.push_back({"run.t_end", t_end});
  overrides.push_back({"run.rtol", "1e-11"});
  const sim::Scene scene = test::scene_file("pantograph", overrides);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  return sim::summarize(scene, run);
}

// Every joint's determinate peak hinge force within 1e-4 of the reference's.
void expect_same_hinge_peaks(const sim::RunSummary& reference, const sim::RunSummary& other,
                             const sim::Override& setting) {
  for (std::size_t j = 0; j < reference.peak_hinge_force.size(); ++j) {
    const double a = reference.peak_hinge_force[j].peak.value, b = other.peak_hinge_force[j].peak.value;
    EXPECT_NEAR(b, a, 1e-4 * a) << setting.path << " = " << setting.value << ", "
                                << reference.peak_hinge_force[j].joint;
  }
}

TEST(LoadDeterminacy, DeterminateHingePeaksDoNotDependOnTheRegulatorsSettings) {
  // Two decades of regularization up to the pantograph's automatic 2e-6
  // (at 2e-5, ten times that, the weak direction at the latch-up, 1e-6 of
  // the strongest, is held ten times softer and the motion itself moves the peaks by up to
  // 1.3e-4); two decades of bandwidth about the file's v_max of 2000 rad/s,
  // from 19 times the mechanism's fastest rate (53 rad/s, the latches'): at
  // 700 (13 times) the softer regulator moves the latch-up itself and the
  // peaks by 1.1e-4. At 100,000 the right-hand side's round-off (as v_max^2)
  // makes the run raise its tolerance four times (to 1.6e-10); the peaks
  // stay within 5.5e-5 of the file's.
  const std::vector<std::vector<sim::Override>> settings{{{"regulator.regularization", "2e-8"}},
                                                         {{"regulator.regularization", "2e-7"}},
                                                         {{"regulator.v_max", "1000"}},
                                                         {{"regulator.v_max", "100000"}}};
  const sim::RunSummary nominal = run_pantograph({});
  ASSERT_EQ(nominal.loads_determinate, std::optional<bool>(false));
  // The latch-up (all eight latches at 7.392 s) passes the branch point.
  const auto covers = [](const sim::RunSummary& s, double t) {
    return std::any_of(s.indeterminate_spans.begin(), s.indeterminate_spans.end(),
                       [t](const auto& span) { return span[0] <= t && t <= span[1]; });
  };
  EXPECT_TRUE(covers(nominal, 7.5));
  for (const auto& overrides : settings) {
    expect_same_hinge_peaks(nominal, run_pantograph(overrides), overrides[0]);
  }
  // The peak of the rigid model at the latch-up, as two independent
  // engines have it.
  EXPECT_NEAR(nominal.peak_hinge_force[0].peak.value, 162.76, 0.01);
}

TEST(LoadDeterminacy, AnAsymmetricLatchUpReportsMinimumNormLoadsNotTheRegulatorsSelfStress) {
  // One spring 2 % stiffer: the regulator's own loop forces peak near
  // 76 kN there, set by its regularization (442 kN at 1e-7, 11 kN at 1e-4).
  const sim::RunSummary nominal = run_pantograph({});
  for (const char* regularization : {"2e-7", "2e-5"}) {
    const sim::RunSummary off =
        run_pantograph({{"springs.j1.stiffness", "0.102"}, {"regulator.regularization", regularization}});
    ASSERT_EQ(off.loads_determinate, std::optional<bool>(false));
    for (std::size_t j = 0; j < off.peak_hinge_force_indeterminate.size(); ++j)
      EXPECT_LT(off.peak_hinge_force_indeterminate[j].peak.value, 5 * nominal.peak_hinge_force[0].peak.value)
          << off.peak_hinge_force_indeterminate[j].joint << " at regularization " << regularization;
  }
}

TEST(LoadDeterminacy, AfterAnAsymmetricBranchPassageTheDeterminatePeaksDoNotDependOnTheRegulatorsSettings) {
  // Past the branch point the regulator, not the mechanism, placed the
  // state along the weak directions; where the two forces agree again the
  // rigid loads there were 1e3..1e5 N and followed the settings (12.4 kN at
  // regularization 2e-6, 11.4 kN at 2e-7, 113 N at 2e-5). Those steps are
  // indeterminate now, and what stays determinate is the deployment up to
  // the branch passage.
  const std::vector<sim::Override> off_nominal{{"springs.j1.stiffness", "0.102"}};
  const sim::RunSummary reference = run_pantograph(off_nominal);
  ASSERT_FALSE(reference.indeterminate_spans.empty());
  const auto& last = reference.indeterminate_spans.back();
  EXPECT_NEAR(last[1], 7.6, 1e-9) << "indeterminate from the branch passage to the end";
  const std::vector<sim::Override> settings{{"regulator.regularization", "2e-7"},
                                            {"regulator.regularization", "2e-5"},
                                            {"regulator.v_max", "1000"},
                                            {"regulator.v_max", "4000"}};
  for (const sim::Override& setting : settings) {
    std::vector<sim::Override> overrides = off_nominal;
    overrides.push_back(setting);
    const sim::RunSummary other = run_pantograph(overrides);
    expect_same_hinge_peaks(reference, other, setting);
    ASSERT_FALSE(other.indeterminate_spans.empty());
    EXPECT_NEAR(other.indeterminate_spans.front()[0], reference.indeterminate_spans.front()[0], 1e-3)
        << setting.path << " = " << setting.value;
  }
}

TEST(LoadDeterminacy, AToggleClosingOnItsBranchPointHasNoDeterminatePeakOnTheWay) {
  // j1's spring broken: the array closes on its deployed branch point
  // asymmetrically, as a toggle, and the rigid loads grow as 1/distance
  // until the regulator departs from them, which its settings place: the
  // last determinate step's load was 326 .. 1640 N over regularization
  // 2e-5 .. 2e-8. That run-up counts as indeterminate; the determinate
  // peaks are the latch impacts before it (153.6 N at j1, 7.32 s).
  const std::vector<sim::Override> broken{{"springs.j1.stiffness", "0"}};
  const sim::RunSummary reference = run_pantograph(broken, "14.5");
  ASSERT_FALSE(reference.indeterminate_spans.empty());
  // Flagged before the branch point (the lowest rank, at 14.367 s).
  EXPECT_LT(reference.indeterminate_spans.back()[0], 14.367);
  const sim::RunSummary::NamedPeak& j1 = reference.peak_hinge_force[0];
  EXPECT_LT(j1.peak.t, 8.0);
  EXPECT_GT(reference.peak_hinge_force_indeterminate[0].peak.value, 2 * j1.peak.value) << "the run-up";
  const std::vector<sim::Override> settings{{"regulator.regularization", "2e-8"},
                                            {"regulator.regularization", "2e-5"},
                                            {"regulator.v_max", "1000"},
                                            {"regulator.v_max", "4000"}};
  for (const sim::Override& setting : settings) {
    std::vector<sim::Override> overrides = broken;
    overrides.push_back(setting);
    expect_same_hinge_peaks(reference, run_pantograph(overrides, "14.5"), setting);
  }
}

TEST(LoadDeterminacy, AFourBarAwayFromItsSingularPositionsIsDeterminate) {
  const sim::Scene scene = test::scene_file("fourbar", {{"run.t_end", "1"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const sim::RunSummary s = sim::summarize(scene, run);
  EXPECT_EQ(s.loads_determinate, std::optional<bool>(true));
  EXPECT_TRUE(s.indeterminate_spans.empty());
  for (const sim::Sample& sample : run.trajectory.samples)
    EXPECT_EQ(sample.loads.determinacy, sim::Determinacy::determinate) << sample.t;
  // Its one loop's equations stay independent (the rank summary.json and
  // simulate report).
  EXPECT_EQ(run.peaks.closure_rank_at_start, run.trajectory.layout.m);
  EXPECT_EQ(run.peaks.lowest_closure_rank, run.trajectory.layout.m);
}

TEST(LoadDeterminacy, ParallelRodsAreIndeterminateAtTheirFlatPositions) {
  // One rod: a four-bar with the mobility jumping to 2 at the flat
  // position; its loads there are indeterminate, elsewhere determinate.
  const sim::SceneFile file = studies::generate_parallel_rods(1);
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  const sim::RunSummary s = sim::summarize(file.scene, run);
  ASSERT_EQ(s.loads_determinate, std::optional<bool>(false));
  double indeterminate = 0;
  for (const auto& span : s.indeterminate_spans) indeterminate += span[1] - span[0];
  EXPECT_LT(indeterminate, 0.1 * file.scene.run.t_end) << "only near the flat positions";
  // The closure system loses rank there and only there.
  const int m = run.trajectory.layout.m;
  EXPECT_EQ(run.peaks.closure_rank_at_start, m);
  EXPECT_LT(run.peaks.lowest_closure_rank, m);
  EXPECT_GE(run.peaks.lowest_closure_rank, 0);
  EXPECT_LT(std::abs(std::sin(studies::parallel_rods_angles(file.scene, run.peaks.lowest_closure_rank_t)[0])), 0.05)
      << "lowest rank at t = " << run.peaks.lowest_closure_rank_t;
  for (const sim::Sample& sample : run.trajectory.samples) {
    const double crank = studies::parallel_rods_angles(file.scene, sample.t)[0];
    if (std::abs(std::sin(crank)) > 0.2) {
      EXPECT_EQ(sample.loads.determinacy, sim::Determinacy::determinate) << sample.t;
    }
  }
}

// The sparse analysis (sparse_closure_rank.hpp in the sources) takes every
// mechanism beyond the dense one's 48 loop components, and those whose
// regulator asks for the sparse closure solver: here it is held against
// the dense analysis where both apply.
std::vector<sim::Override> with_sparse_analysis(std::vector<sim::Override> overrides) {
  overrides.push_back({"regulator.solver", "sparse"});
  return overrides;
}

TEST(SparseLoadDeterminacy, FindsTheDenseAnalysisIndeterminateSpansAndDeterminatePeaksOnThePantograph) {
  // Nominal (the latch-up passes the branch point) and one spring 2 %
  // stiffer (the asymmetric latch-up). The minimum-norm loads inside the
  // spans differ by design (a smooth filter for a sharp cut: 714 N against
  // 473.6 N at j1 off nominal) and are only held to the bound above.
  const double nominal_peak = run_pantograph({}).peak_hinge_force[0].peak.value;
  for (const std::vector<sim::Override>& overrides :
       {std::vector<sim::Override>{}, std::vector<sim::Override>{{"springs.j1.stiffness", "0.102"}}}) {
    const sim::RunSummary dense = run_pantograph(overrides), sparse = run_pantograph(with_sparse_analysis(overrides));
    ASSERT_EQ(sparse.loads_determinate, std::optional<bool>(false));
    ASSERT_FALSE(dense.indeterminate_spans.empty());
    EXPECT_NEAR(sparse.indeterminate_spans.front()[0], dense.indeterminate_spans.front()[0], 1e-4);
    const double total = sim::total_time(dense.indeterminate_spans);
    EXPECT_NEAR(sim::total_time(sparse.indeterminate_spans), total, 1e-2 * total);
    expect_same_hinge_peaks(dense, sparse, {"regulator.solver", "sparse"});
    for (const auto& peak : sparse.peak_hinge_force_indeterminate)
      EXPECT_LT(peak.peak.value, 5 * nominal_peak) << peak.joint;
  }
}

TEST(SparseLoadDeterminacy, FindsTheFlexiblePantographDeterminateWithTheDenseAnalysisPeaks) {
  // Its loops close through the plates' bending: W keeps its rank, and the
  // panels' vibration loads the hinges (55.7 N in the first 0.5 s).
  auto run = [](std::vector<sim::Override> overrides) {
    overrides.push_back({"run.t_end", "0.5"});
    const sim::Scene scene = test::scene_file("pantograph_flexible", overrides);
    return sim::summarize(scene, sim::simulate(scene, scene.run));
  };
  const sim::RunSummary dense = run({}), sparse = run(with_sparse_analysis({}));
  EXPECT_EQ(dense.loads_determinate, std::optional<bool>(true));
  EXPECT_EQ(sparse.loads_determinate, std::optional<bool>(true));
  expect_same_hinge_peaks(dense, sparse, {"regulator.solver", "sparse"});
}

TEST(SparseLoadDeterminacy, FindsAFourBarDeterminateAndParallelRodsIndeterminateOnlyAtTheirFlatPositions) {
  const sim::Scene fourbar = test::scene_file("fourbar", with_sparse_analysis({{"run.t_end", "1"}}));
  const sim::RunResult run = sim::simulate(fourbar, fourbar.run);
  EXPECT_EQ(sim::summarize(fourbar, run).loads_determinate, std::optional<bool>(true));
  EXPECT_EQ(run.peaks.closure_rank_at_start, -1) << "the sparse analysis does not count the rank";

  sim::SceneFile rods = studies::generate_parallel_rods(1);
  rods.scene.regulator.solver = sim::ClosureSolverKind::sparse;
  const sim::RunResult rods_run = sim::simulate(rods.scene, rods.scene.run);
  const sim::RunSummary s = sim::summarize(rods.scene, rods_run);
  ASSERT_EQ(s.loads_determinate, std::optional<bool>(false));
  EXPECT_LT(sim::total_time(s.indeterminate_spans), 0.1 * rods.scene.run.t_end) << "only near the flat positions";
  for (const sim::Sample& sample : rods_run.trajectory.samples) {
    const double crank = studies::parallel_rods_angles(rods.scene, sample.t)[0];
    if (std::abs(std::sin(crank)) > 0.2) {
      EXPECT_EQ(sample.loads.determinacy, sim::Determinacy::determinate) << sample.t;
    }
  }
}

TEST(SparseLoadDeterminacy, TheLargeRigidArraysMinimumNormLoadsDoNotFollowTheRegulatorsSettings) {
  // 30 stages, 90 loop components: its weakest loop mode at the start is
  // 1.2e-10 of the strongest, below the rank tolerance, so the loads are
  // indeterminate throughout. Unassessed, the regulator's own forces gave
  // hinge forces up to 2.75e5 N in the first 0.2 s (5.9e10 N over the
  // whole deployment); the minimum-norm ones agree to 1.1e-5 over two
  // decades of regularization and another bandwidth.
  auto run_array = [](double regularization, std::optional<double> v_max) {
    sim::SceneFile file = studies::generate_pantograph(30);
    file.scene.run.t_end = 0.02;
    file.scene.run.sample = 0.01;
    file.scene.run.rtol = 1e-9;
    file.scene.regulator.regularization = regularization;
    file.scene.regulator.v_max = v_max;
    const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
    EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
    const sim::RunSummary s = sim::summarize(file.scene, run);
    EXPECT_EQ(s.loads_determinate, std::optional<bool>(false)) << "assessed, and indeterminate";
    return run.trajectory.samples.back().loads.reaction;
  };
  const std::vector<sim::Vec6> reference = run_array(2e-9, std::nullopt);
  double largest = 0;
  for (const sim::Vec6& r : reference) largest = std::max(largest, r.head<3>().norm());
  EXPECT_LT(largest, 3e3);
  for (const auto& [regularization, v_max] : std::vector<std::pair<double, std::optional<double>>>{
           {2e-8, std::nullopt}, {2e-10, std::nullopt}, {2e-9, 3000.0}}) {
    const std::vector<sim::Vec6> other = run_array(regularization, v_max);
    for (std::size_t j = 0; j < reference.size(); ++j)
      EXPECT_LT((other[j].head<3>() - reference[j].head<3>()).norm(), 1e-4 * largest)
          << "joint " << j << " at regularization " << regularization;
  }
}

}  // namespace
}  // namespace unfurl
