// BDF's order capped from the latch-up on (run.max_order_after_latch): the
// deployment is stepped as without the cap, the ring-down at the capped
// order, and the answer is the same to the tolerance. Where it pays (a
// 30-stage array's ring-down held by order 4 at 2.2e-4 s steps) a run
// takes a minute; here the pantograph shows that the cap acts, and where:
// its own ring-down is not held so, and order 2 takes more steps there.
#include <gtest/gtest.h>

#include "same_before_first_latch.hpp"
#include "support.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

sim::RunResult run_pantograph(const std::string& max_order) {
  const sim::Scene scene = test::scene_file(
      "pantograph", {{"run.rtol", "1e-7"}, {"run.atol", "1e-9"}, {"run.max_order_after_latch", max_order}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  return run;
}

// rtol 1e-7: 2,072 steps uncapped, 4,342 at order 2, their angles 2.1e-7 rad apart.
TEST(MaxOrderAfterLatch, StepsTheRingDownAtTheCappedOrderAndLeavesTheDeploymentAsItWas) {
  const sim::RunResult plain = run_pantograph("5"), capped = run_pantograph("2");
  ASSERT_NO_FATAL_FAILURE(test::expect_the_same_before_the_first_latch(plain, capped));
  EXPECT_GT(capped.stats.steps, 1.5 * plain.stats.steps);
  EXPECT_LT(test::largest_angle_difference(test::scene_file("pantograph").model, plain, capped), 1e-6);
}

}  // namespace
}  // namespace unfurl
