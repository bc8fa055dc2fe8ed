// The reference scenes beyond the pantograph: the exact stowed start and the
// z-fold.
#include <gtest/gtest.h>

#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

TEST(PantographStowed, RunsToTheEndAndReportsWhichJointsLatched) {
  const sim::Scene scene = test::scene_file("pantograph_stowed");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_DOUBLE_EQ(run.trajectory.t_end(), 20.0);
  const sim::RunSummary s = sim::summarize(scene, run);
  // Every latch is accounted for: latched with a time, or listed unlatched.
  EXPECT_EQ(s.latch_times.size() + s.unlatched.size(), scene.latches().size());
  EXPECT_LT(s.max_closure_gap, 1e-5);
  std::printf("stowed start: %zu of 8 latched;", s.latch_times.size());
  for (const auto& [joint, t] : s.latch_times) std::printf(" %s@%.4f", joint.c_str(), t);
  std::printf("\n");
}

TEST(Zfold, DeploysAndLatches) {
  const sim::Scene scene = test::scene_file("zfold");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_EQ(run.trajectory.events.size(), 4u);
  // Deployed: every joint ends near q = 0, held by its latch.
  for (double q : std::vector<double>(run.trajectory.samples.back().y.begin(),
                                      run.trajectory.samples.back().y.begin() + 4))
    EXPECT_LT(std::abs(q), 0.01);
  // A tree: no loop states at all.
  EXPECT_EQ(run.trajectory.layout.m, 0);
}

TEST(Zfold, EveryIntegratorDeploysIt) {
  const sim::Scene scene = test::scene_file("zfold");
  const sim::RunResult reference = sim::simulate(scene, scene.run);
  for (sim::IntegratorKind kind : sim::all_integrators()) {
    sim::RunSettings settings = scene.run;
    settings.integrator = kind;
    settings.dt = 1e-4;
    const sim::RunResult run = sim::simulate(scene, settings);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::integrator_name(kind) << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.events.size(), 4u) << sim::integrator_name(kind);
    for (std::size_t e = 0; e < 4; ++e)
      EXPECT_NEAR(run.trajectory.events[e].t, reference.trajectory.events[e].t, 1e-4) << sim::integrator_name(kind);
  }
}

}  // namespace
}  // namespace unfurl
