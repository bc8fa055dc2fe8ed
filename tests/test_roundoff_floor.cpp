// The right-hand side's round-off (roundoff_floor.hpp): set by the loops'
// true gap times v_max^2, absent from trees, and what the run reports.
#include <gtest/gtest.h>

#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/roundoff_floor.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

double floor_of(const sim::Scene& scene) {
  sim::Dynamics dynamics(scene);
  return sim::roundoff_floor(dynamics, 0, dynamics.initial_state());
}

TEST(RoundoffFloor, TreesHaveNone) { EXPECT_LT(floor_of(test::scene_file("zfold")), 1e-15); }

// Between the tolerances where the pantograph's steps stay put (1e-10) and
// where they grow six-fold (1e-11).
TEST(RoundoffFloor, ThePantographsLiesBetweenTheTolerancesWhereItsStepsJump) {
  const double floor = floor_of(test::scene_file("pantograph"));
  EXPECT_GT(floor, 1e-11);
  EXPECT_LT(floor, 1e-10);
}

// The gap's round-off reaches f through v_max^2 (the regulator's v^2 (g + u)).
TEST(RoundoffFloor, GrowsAsTheBandwidthSquared) {
  const double at_2000 = floor_of(test::scene_file("pantograph"));
  const double at_8000 = floor_of(test::scene_file("pantograph", {{"regulator.v_max", "8000"}}));
  EXPECT_GT(at_8000 / at_2000, 16 / 2.0);
  EXPECT_LT(at_8000 / at_2000, 16 * 2.0);
}

TEST(RoundoffFloor, TheRunReportsIt) {
  const sim::Scene scene = test::scene_file("pantograph", {{"run.t_end", "0.1"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_DOUBLE_EQ(run.roundoff_floor, floor_of(scene));
}

}  // namespace
}  // namespace unfurl
