// The loop regulator: an open start closes, max_closure fails a run on the
// geometric gap, and only the loop components some motion can excite carry
// a regulator state.
#include <gtest/gtest.h>

#include "support.hpp"
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/mechanism_scales.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl {
namespace {

TEST(LoopRegulator, ResidualOfAnOpenStartDecays) {
  // Start the four-bar about 1 mm / 1 mrad open: the restoring loop force
  // must pull it shut within a few regulator time constants (1/v_max).
  sim::Scene scene = test::scene_file("fourbar", {{"closure_tolerance", "0.01"},
                                                  {"initial.q.crank_pivot", "1.5717963267948966"},
                                                  {"run.t_end", "0.05"},
                                                  {"run.sample", "0.001"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const auto& samples = run.trajectory.samples;
  EXPECT_GT(samples.front().closure[0].distance, 1e-4);
  // The regulator acts on the geometric gap itself: it closes to round-off
  // of the regulator's designed error, not only to first order.
  EXPECT_LT(samples.back().closure[0].distance, 1e-9);
  EXPECT_LT(samples.back().closure[0].angle, 1e-9);
}

TEST(LoopRegulator, MaxClosureFailsARunOnTheGeometricGap) {
  // The pantograph's gap, held at the integrator's tolerance, reaches about
  // 1e-11 of its length: a limit below that stops the run where it is
  // first exceeded, at a step's end, with what was computed kept. The limit
  // is dimensionless (rad, or a distance over the mechanism's length).
  const sim::Scene scene = test::scene_file("pantograph", {{"run.max_closure", "5e-12"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::failed);
  EXPECT_EQ(run.failure.check, "closure");
  EXPECT_GT(run.failure.t, 0.0);
  EXPECT_GT(std::max(run.peaks.gap_m.value / sim::mechanism_length(scene.model), run.peaks.gap_rad.value), 5e-12);
  EXPECT_NE(run.failure.reason.find("a loop opened by"), std::string::npos);
  EXPECT_LE(run.trajectory.t_end(), run.failure.t);
}

double largest_gap(const sim::RunResult& run, double from, double to) {
  double gap = 0;
  for (const sim::Sample& s : run.trajectory.samples)
    if (s.t >= from && s.t <= to) gap = std::max(gap, s.closure[0].distance);
  return gap;
}

TEST(LoopRegulator, FourbarsGapStaysBelowANanometreAndDoesNotGrow) {
  // Without damping nothing dissipates an integration error: the feedback
  // on the geometric gap must hold it at the tolerance's level for good.
  // (Over 1e4 s the same run stays below 6.5e-10 m; see the README.)
  const sim::Scene scene =
      test::scene_file("fourbar", {{"run.t_end", "200"}, {"run.rtol", "1e-8"}, {"run.sample", "0.5"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const double early = largest_gap(run, 10, 100), late = largest_gap(run, 100, 200);
  EXPECT_LT(largest_gap(run, 0, 200), 1e-9);
  EXPECT_GT(early, 0.0);
  EXPECT_LT(late, 3 * early) << "the gap grows: " << early << " m over [10, 100] s, " << late << " m over [100, 200] s";
}

TEST(LoopRegulator, StiffLatchesEndAtRestWithTheSpringsEnergyAndNoStuckResidual) {
  // Latches at 1e8 N m/rad ring at about 1e4 rad/s, close to the
  // regulator's own rate: the run must still settle with the loops shut and
  // the energy the springs leave (pi^2 / 10 J), not a wound-up residual.
  std::vector<sim::Override> overrides = {{"run.rtol", "1e-8"}};
  for (int l = 0; l < 8; ++l) overrides.push_back({"latches." + std::to_string(l) + ".stiffness", "1e8"});
  const sim::Scene scene = test::scene_file("pantograph", overrides);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const sim::RunSummary summary = sim::summarize(scene, run);
  const double springs_energy = 0.9869604401089358;
  EXPECT_NEAR(summary.energy_final, springs_energy, 0.01 * springs_energy);
  EXPECT_LT(run.peaks.gap_m.value, 1e-7);
  const sim::Sample& last = run.trajectory.samples.back();
  for (double rate : last.q_dot) EXPECT_LT(std::abs(rate), 1e-3);
}

TEST(LeaveOut, TreeSceneCarriesNoRegulatorState) {
  const sim::Scene scene = test::scene_file("zfold");
  sim::Dynamics dynamics(scene);
  EXPECT_EQ(dynamics.layout().m, 0);
  EXPECT_EQ(dynamics.size(), 2 * scene.model.nq);
  EXPECT_EQ(dynamics.regulator(), nullptr);
}

TEST(LeaveOut, PlanarLoopCarriesThreeComponents) {
  const sim::Scene scene = test::scene_file("fourbar");
  sim::Dynamics dynamics(scene);
  ASSERT_NE(dynamics.regulator(), nullptr);
  EXPECT_EQ(dynamics.layout().m, 3);  // v_y, v_z, w_x: the in-plane ones
  for (const sim::LoopComponent& c : dynamics.regulator()->components())
    EXPECT_TRUE(c.axis == 1 || c.axis == 2 || c.axis == 3);
  EXPECT_EQ(dynamics.size(), 2 * scene.model.nq + 3);  // (q, p, u)
}

TEST(LeaveOut, PantographCarriesNineComponents) {
  sim::Dynamics dynamics(test::scene_file("pantograph"));
  EXPECT_EQ(dynamics.layout().m, 9);
  EXPECT_EQ(dynamics.size(), 31);  // (q, p, u): 11 + 11 + 9
}

TEST(LeaveOut, SceneWithoutLatchesHasNoEvents) {
  const sim::Scene scene = test::scene_file("double_pendulum");
  sim::Dynamics dynamics(scene);
  EXPECT_EQ(dynamics.latch_count(), 0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_TRUE(run.trajectory.events.empty());
}

}  // namespace
}  // namespace unfurl
