// BDF's stability-limit detection (run.stability_limit_detection): in a
// latched ring-down, lightly damped, BDF's orders 3 to 5 are unstable and
// CVODE steps under their limit; with the detection it lowers the order
// there instead, and the answer is the same to the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "same_before_first_latch.hpp"
#include "support.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

sim::RunResult run_compliant_pantograph(const std::string& detection) {
  const sim::Scene scene = test::scene_file("pantograph_compliant", {{"run.stability_limit_detection", detection}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  return run;
}

// The compliant pantograph's whole 20 s (rtol 1e-10): 33,961 steps without
// the detection, 30,402 with it, the two within 1.4e-9 rad of each other
// and 4.7e-8 rad of a run at rtol 1e-12.
TEST(StabilityLimitDetection, LowersTheOrderInTheLatchedRingDownWithoutMovingTheAnswer) {
  const sim::RunResult plain = run_compliant_pantograph("false"), detected = run_compliant_pantograph("true");
  EXPECT_LT(detected.stats.steps, 0.95 * plain.stats.steps);
  ASSERT_EQ(plain.trajectory.samples.size(), detected.trajectory.samples.size());
  EXPECT_LT(test::largest_angle_difference(test::scene_file("pantograph_compliant").model, plain, detected), 1e-7);
}

// From the latch-up on only: the deployment is stepped exactly as without
// the detection, and the ring-down as with it.
TEST(StabilityLimitDetection, AfterTheLatchUpLeavesTheDeploymentAsItWas) {
  const sim::RunResult plain = run_compliant_pantograph("false"), after = run_compliant_pantograph("after_latch");
  ASSERT_NO_FATAL_FAILURE(test::expect_the_same_before_the_first_latch(plain, after));
  EXPECT_LT(after.stats.steps, 0.95 * plain.stats.steps);
  EXPECT_LT(test::largest_angle_difference(test::scene_file("pantograph_compliant").model, plain, after), 1e-7);
}

}  // namespace
}  // namespace unfurl
