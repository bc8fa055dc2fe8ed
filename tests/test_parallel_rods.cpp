// A mechanism whose loops are redundant everywhere and singular twice a
// period: two cranks joined by N parallel rods (studies::generate_parallel_rods),
// swung through their flat position, against its one-degree-of-freedom
// closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

TEST(ParallelRods, FollowTheirClosedFormThroughTheFlatPositionAtDefaultSettings) {
  for (int rods = 1; rods <= 5; ++rods) {
    const sim::SceneFile file = studies::generate_parallel_rods(rods);
    const sim::Scene& scene = file.scene;
    ASSERT_EQ(scene.run.t_end, 10);
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << rods << " rods: " << sim::describe(run.failure);
    double worst = 0;
    int flat_passes = 0;
    double previous = 0;
    for (const sim::Sample& s : run.trajectory.samples) {
      const std::vector<double> exact = studies::parallel_rods_angles(scene, s.t);
      for (int j = 0; j < scene.model.size(); ++j) worst = std::max(worst, std::abs(s.y[j] - exact[j]));
      if (s.t > 0 && std::signbit(exact[0]) != std::signbit(previous)) ++flat_passes;
      previous = exact[0];
    }
    EXPECT_GE(flat_passes, 4) << rods << " rods: the run must pass the flat position";
    EXPECT_LT(worst, 1e-6) << rods << " rods";
  }
}

}  // namespace
}  // namespace unfurl
