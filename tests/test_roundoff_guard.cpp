// The run's guard against chasing the right-hand side's round-off
// (roundoff_guard.hpp): it raises the tolerances only where the Newton
// iteration keeps failing on noise, by the least that stops it, and a run
// that converges is left as it was.
#include <gtest/gtest.h>

#include "support.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

sim::RunResult run_pantograph(std::vector<sim::Override> overrides) {
  const sim::Scene scene = test::scene_file("pantograph", overrides);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  return run;
}

// Latched at its branch point the pantograph's f carries round-off of about
// its own tolerance (1e-10): without the guard the ring-down from 7.39 s to
// 20 s took 31,000 steps with a Newton failure in three.
TEST(RoundoffGuard, ThePantographsLatchedRingDownTakesNoMoreStepsThanItsDeployment) {
  const sim::RunResult guarded = run_pantograph({{"run.t_end", "12"}});
  const sim::RunResult held = run_pantograph({{"run.t_end", "12"}, {"run.roundoff_guard", "false"}});
  ASSERT_FALSE(guarded.tolerance_raises.empty());
  EXPECT_TRUE(held.tolerance_raises.empty());
  // Before the first raise the runs are the same, latch-up included.
  const double first_raise = guarded.tolerance_raises.front().t;
  const double first_latch = guarded.trajectory.events.front().t;
  EXPECT_GT(first_raise, first_latch);
  ASSERT_EQ(guarded.trajectory.events.size(), held.trajectory.events.size());
  for (std::size_t k = 0; k < held.trajectory.events.size(); ++k)
    EXPECT_EQ(guarded.trajectory.events[k].t, held.trajectory.events[k].t);
  for (std::size_t k = 0; k < held.trajectory.samples.size() && held.trajectory.samples[k].t < first_raise; ++k)
    EXPECT_EQ(guarded.trajectory.samples[k].y, held.trajectory.samples[k].y) << "t = " << held.trajectory.samples[k].t;
  // The deployment to the latch-up takes about 2,200 steps.
  EXPECT_LT(guarded.stats.steps, 4000);
  EXPECT_GT(held.stats.steps, 3 * guarded.stats.steps);
  // The least raise: never above twice the floor measured there, never below
  // what was asked.
  for (const sim::ToleranceRaise& r : guarded.tolerance_raises) {
    EXPECT_LE(r.atol, 2 * r.floor * (1 + 1e-12));
    EXPECT_GE(r.rtol, guarded.settings.rtol);
    EXPECT_GE(r.atol, guarded.settings.atol);
  }
}

// The four-bar at rtol 1e-8: samples of its floor come near its tolerance,
// but its Newton iteration fails once in hundreds of steps, so nothing is
// raised and its gap stays where the regulator's test holds it.
TEST(RoundoffGuard, ARunWhoseNewtonIterationConvergesIsLeftAsItWas) {
  const sim::Scene scene = test::scene_file("fourbar", {{"run.t_end", "20"}, {"run.rtol", "1e-8"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_TRUE(run.tolerance_raises.empty());
  EXPECT_GT(run.stats.nonlinear_failures, 0);
}

// The generated 100-stage array at its file's rtol 1e-10 starts below its
// floor (1.7e-10), and its Newton iteration fails one step in 17: looked at
// only after ten failures within 100 steps, it ran 4.1 ms in 1,700 steps
// chasing round-off before the raise.
TEST(RoundoffGuard, ARunBelowItsFloorFromTheStartIsRaisedWithinItsFirstMillisecond) {
  const sim::Scene scene = studies::generate_pantograph(100).scene;
  sim::RunSettings settings = scene.run;
  settings.t_end = 0.01;
  const sim::RunResult run = sim::simulate(scene, settings);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  ASSERT_FALSE(run.tolerance_raises.empty());
  EXPECT_LT(run.tolerance_raises.front().t, 1e-3);
  EXPECT_LT(run.stats.steps, 600);
}

TEST(RoundoffGuard, TheSceneFileSwitchesItOffAndWritesThatBack) {
  const sim::SceneFile off = sim::read_builtin_scene("pantograph", {{"run.roundoff_guard", "false"}});
  EXPECT_FALSE(off.scene.run.roundoff_guard);
  const std::string written = sim::write_scene_text(off);
  EXPECT_NE(written.find("roundoff_guard: false"), std::string::npos);
  EXPECT_FALSE(sim::read_scene_text(written, "written").scene.run.roundoff_guard);
  EXPECT_EQ(sim::write_scene_text(sim::read_builtin_scene("pantograph")).find("roundoff_guard"), std::string::npos);
  try {
    sim::read_builtin_scene("pantograph", {{"run.roundoff_guard", "sometimes"}});
    ADD_FAILURE() << "a guard that is neither true nor false was read";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("run.roundoff_guard"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unfurl
