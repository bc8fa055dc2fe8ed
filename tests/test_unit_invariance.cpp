// Dimensional analysis: a mechanism scaled by lengths x L and masses x M,
// time unchanged, has the same joint angles as functions of time. A solver
// whose tolerances, gains or regularization depend on the units shows it
// here, in its angles or in the steps it takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "support.hpp"
#include "unfurl/sim/regulator.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "unfurl/studies/scene_scaling.hpp"

namespace unfurl {
namespace {

// (L, M) spanning 1e-3..1e1 and 1e-6..1e3, corners and a middle.
const std::pair<double, double> kUnits[] = {{1e-3, 1e-6}, {1e-2, 1e-3}, {1e1, 1e3}, {1e-3, 1e3}, {1e1, 1e-6}};

// Angles and latch events over the scene's run; step counts up to
// `steps_until` (the first latch: the latched ring-down's step count moves
// by up to 2x with a change of 1e-8 in a mass, units or not, as its Newton
// iterations fail or not at round-off).
void expect_unit_invariant(const sim::SceneFile& original, double steps_until) {
  const sim::RunResult base = sim::simulate(original.scene, original.scene.run);
  ASSERT_EQ(base.status, sim::RunStatus::finished) << sim::describe(base.failure);
  for (const auto& [L, M] : kUnits) {
    const sim::SceneFile scaled = studies::scale_scene(original, L, M);
    const sim::RunResult run = sim::simulate(scaled.scene, scaled.scene.run);
    const std::string units = "L = " + std::to_string(L) + ", M = " + std::to_string(M);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << units << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.samples.size(), base.trajectory.samples.size()) << units;
    EXPECT_LT(test::largest_angle_difference(original.scene.model, run, base), 1e-7) << units;
    sim::RunSettings until = original.scene.run;
    until.t_end = steps_until;
    const double steps = sim::simulate(scaled.scene, until).stats.steps;
    const double base_steps = sim::simulate(original.scene, until).stats.steps;
    EXPECT_NEAR(steps, base_steps, 0.3 * base_steps) << units;
    EXPECT_EQ(run.trajectory.events.size(), base.trajectory.events.size()) << units;
    // Forces scale with M L (time unchanged): the determinate hinge peaks,
    // and where the loads stop being determinate.
    for (std::size_t j = 0; j < base.peaks.hinge_force.size(); ++j) {
      const double a = base.peaks.hinge_force[j].value, b = run.peaks.hinge_force[j].value / (M * L);
      EXPECT_NEAR(b, a, 1e-4 * a) << units << ", joint " << j;
    }
    ASSERT_EQ(run.peaks.indeterminate_spans.empty(), base.peaks.indeterminate_spans.empty()) << units;
    if (!base.peaks.indeterminate_spans.empty()) {
      EXPECT_NEAR(run.peaks.indeterminate_spans[0][0], base.peaks.indeterminate_spans[0][0], 1e-3) << units;
    }
    ASSERT_TRUE(run.closure && base.closure);
    // The closure's own scales follow the units; its tuning does not.
    EXPECT_NEAR(run.closure->length, L * base.closure->length, 1e-12 * L * base.closure->length) << units;
    EXPECT_NEAR(run.closure->rate, base.closure->rate, 1e-9 * base.closure->rate) << units;
    EXPECT_NEAR(run.closure->v_max, base.closure->v_max, 1e-9 * base.closure->v_max) << units;
  }
}

TEST(UnitInvariance, PantographThroughItsLatchUpInAnyUnits) {
  expect_unit_invariant(sim::read_builtin_scene("pantograph", {{"run.t_end", "9"}}), 7.3);
}

// A scene whose one element with a peak carries a joint torque: its motion
// is the same in any units and its peak torque scales as M L^2.
void expect_joint_torque_invariant(const sim::SceneFile& original) {
  const sim::RunResult base = sim::simulate(original.scene, original.scene.run);
  ASSERT_EQ(base.status, sim::RunStatus::finished);
  ASSERT_EQ(base.peaks.element.size(), 1u);
  ASSERT_GT(base.peaks.element[0].value, 0.0);
  for (const auto& [L, M] : kUnits) {
    const sim::SceneFile scaled = studies::scale_scene(original, L, M);
    const sim::RunResult run = sim::simulate(scaled.scene, scaled.scene.run);
    const std::string units = "L = " + std::to_string(L) + ", M = " + std::to_string(M);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << units;
    ASSERT_EQ(run.trajectory.samples.size(), base.trajectory.samples.size()) << units;
    EXPECT_LT(test::largest_angle_difference(original.scene.model, run, base), 1e-7) << units;
    EXPECT_NEAR(run.peaks.element[0].value / (M * L * L), base.peaks.element[0].value,
                1e-4 * base.peaks.element[0].value)
        << units;
  }
}

// A driver turns the loop's crank. Step counts are not asserted: they are
// not set by the units but by round-off. The driven crank leaves the loop no
// freedom, so the regulator's poles set the error estimate, and BDF's order
// at its stability limit makes the count chaotic: 5253 steps as written,
// 8885 at L = 10, M = 1e3, and 14,386 at L = 1 + 1e-9, where only round-off
// differs (4408, 5361 and 5802 with stability-limit detection).
TEST(UnitInvariance, ADrivenCrankInAnyUnits) {
  expect_joint_torque_invariant(sim::read_builtin_scene(
      "fourbar", {{"drivers", "[{joint: crank_pivot, profile: spin_up, amount: 3, duration: 1}]"}, {"run.t_end", "3"}}));
}

// A joint limit catches the z-fold's first panel hinge and throws it back
// (at 8.6 s; its torque is 0 until then).
TEST(UnitInvariance, AJointLimitInAnyUnits) {
  expect_joint_torque_invariant(sim::read_builtin_scene(
      "zfold", {{"limits", "[{joint: j2, lower: 0.6, stiffness: 20, damping: 0.2}]"}, {"run.t_end", "10"}}));
}

// Flexible panels: the z-fold with beam panels through its first latch-up.
// The structure is meshed and reduced again in the new units; its angles,
// latch time and steps follow the original's and its largest deflection
// scales as L. At rtol 1e-10: at the scene's 1e-8 the run is only that
// repeatable (a mass changed by 1e-9 moves its angles by 6e-7 rad and its
// steps by 12 %, units or not), here by 1.2e-8 rad; the units move them by
// under 1e-8.
void expect_flexible_invariant(const sim::SceneFile& zfold, const std::string& deflection_column) {
  const sim::RunResult base = sim::simulate(zfold.scene, zfold.scene.run);
  ASSERT_EQ(base.status, sim::RunStatus::finished) << sim::describe(base.failure);
  ASSERT_EQ(base.trajectory.events.size(), 1u);
  const int deflection = sim::find_load_column(base.trajectory.load_columns, deflection_column);
  ASSERT_GE(deflection, 0);
  const auto largest_deflection = [deflection](const sim::RunResult& run) {
    double largest = 0;
    for (const sim::Sample& x : run.trajectory.samples) largest = std::max(largest, x.loads.element[deflection]);
    return largest;
  };
  for (const auto& [L, M] : kUnits) {
    const sim::SceneFile scaled = studies::scale_scene(zfold, L, M);
    const sim::RunResult run = sim::simulate(scaled.scene, scaled.scene.run);
    const std::string units = "L = " + std::to_string(L) + ", M = " + std::to_string(M);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << units << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.samples.size(), base.trajectory.samples.size()) << units;
    EXPECT_LT(test::largest_angle_difference(zfold.scene.model, run, base), 1e-7) << units;
    ASSERT_EQ(run.trajectory.events.size(), 1u) << units;
    EXPECT_NEAR(run.trajectory.events[0].t, base.trajectory.events[0].t, 1e-7) << units;
    EXPECT_NEAR(largest_deflection(run) / L, largest_deflection(base), 1e-4 * largest_deflection(base)) << units;
    EXPECT_NEAR(run.stats.steps, base.stats.steps, 0.3 * base.stats.steps) << units;
  }
}

sim::SceneFile zfold_through_first_latch(const std::string& name) {
  return sim::read_builtin_scene(name, {{"run.t_end", "3.2"}, {"run.rtol", "1e-10"}, {"run.atol", "1e-12"}});
}

TEST(UnitInvariance, FlexiblePanelsInAnyUnits) {
  expect_flexible_invariant(zfold_through_first_latch("zfold_flexible"), "deflection.panel_A3");
}

// The same with plate panels (a plate's bending stiffness D scales as M
// L^2, its mass per area as M / L^2).
TEST(UnitInvariance, FlexiblePlatesInAnyUnits) {
  expect_flexible_invariant(zfold_through_first_latch("zfold_plates"), "deflection.panel_A3");
}

// And a body read from an FE model (its node coordinates, lumped masses,
// modal matrices and shapes' rotations scaled with it): the example
// magnetometer boom through its latch-up.
TEST(UnitInvariance, AnFEModelInAnyUnits) {
  expect_flexible_invariant(sim::read_scene_file(std::string(UNFURL_SOURCE_DIR) + "/examples/fem/magnetometer_boom.yaml",
                                                 {{"run.t_end", "5.2"}, {"run.rtol", "1e-10"}, {"run.atol", "1e-12"}}),
                            "deflection.boom");
}

// Loops closing through flexible plates: a generated 4-stage flexible
// pantograph (its regularization and bandwidth written by the generator,
// its plates meshed and reduced again in the new units) over its first
// 0.02 s after release, where the plates ring and the loops carry them.
TEST(UnitInvariance, AGeneratedFlexibleArrayInAnyUnits) {
  sim::SceneFile array = studies::generate_flexible_pantograph(4);
  array.scene.run.t_end = 0.02;
  array.scene.run.sample = 0.001;
  array.scene.run.rtol = 1e-10;
  array.scene.run.atol = 1e-12;
  expect_unit_invariant(array, 0.02);
}

// Forces at a flexible body's points in other units: a flexible pendulum
// swinging under gravity, pulled by a damped point spring and a bushing at
// its tip and pushed there by a follower force. Its angle follows the
// original's (measured within 2e-10 rad), its deflection scales as L (1e-9
// m), its steps within 4 %.
TEST(UnitInvariance, ForcesOnAFlexibleBodyInAnyUnits) {
  const std::string pendulum = R"(
name: flexible pendulum
base: {name: ground}
gravity: [0, 0, -9.81]
bodies:
  - name: beam
    parent: ground
    flexible:
      beam: {length: 1, axial_stiffness: 1.0e7, bending_stiffness: [200, 500], torsional_stiffness: 400,
             mass_per_length: 1, polar_inertia_per_length: 1.0e-4, elements: 8}
      modes: 4
      damping: [{up_to: 100, ratio: 0.005}, {ratio: 0.3}]
    joint: {name: pivot, type: revolute, axis: [0, 1, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
point_springs:
  - {body_a: ground, point_a: [0.5, 0.3, 0.2], body_b: beam, point_b: [1, 0, 0], stiffness: 40, rest_length: 0.5,
     damping: 0.5}
bushings:
  - {name: stay, body_a: ground, point_a: [1, 0, 0], body_b: beam, point_b: [1, 0, 0], stiffness: [0, 5, 0, 0, 0, 0.1]}
applied_forces:
  - {body: beam, point: [1, 0, 0], force: [0, 0, 2]}
run: {t_end: 1, rtol: 1.0e-10, atol: 1.0e-12, sample: 0.01}
)";
  const sim::SceneFile file = sim::read_scene_text(pendulum, "flexible pendulum");
  const sim::RunResult base = sim::simulate(file.scene, file.scene.run);
  ASSERT_EQ(base.status, sim::RunStatus::finished) << sim::describe(base.failure);
  const int deflection = sim::find_load_column(base.trajectory.load_columns, "deflection.beam");
  ASSERT_GE(deflection, 0);
  for (const auto& [L, M] : kUnits) {
    const sim::SceneFile scaled = studies::scale_scene(file, L, M);
    const sim::RunResult run = sim::simulate(scaled.scene, scaled.scene.run);
    const std::string units = "L = " + std::to_string(L) + ", M = " + std::to_string(M);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << units << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.samples.size(), base.trajectory.samples.size()) << units;
    EXPECT_LT(test::largest_angle_difference(file.scene.model, run, base), 1e-7) << units;
    for (std::size_t k = 0; k < run.trajectory.samples.size(); ++k)
      EXPECT_NEAR(run.trajectory.samples[k].loads.element[deflection] / L,
                  base.trajectory.samples[k].loads.element[deflection], 1e-8)
          << units << ", t = " << run.trajectory.samples[k].t;
    EXPECT_NEAR(run.stats.steps, base.stats.steps, 0.3 * base.stats.steps) << units;
  }
}

TEST(UnitInvariance, AutomaticBandwidthInAnyUnits) {
  const sim::SceneFile automatic =
      sim::read_builtin_scene("pantograph", {{"run.t_end", "3"}, {"regulator.v_max", "auto"}});
  const sim::RunResult run = sim::simulate(automatic.scene, automatic.scene.run);
  ASSERT_TRUE(run.closure);
  EXPECT_TRUE(run.closure->v_max_automatic);
  EXPECT_DOUBLE_EQ(run.closure->v_max, sim::Regulator::kBandwidthPerRate * run.closure->rate);
  expect_unit_invariant(automatic, 3);
}

TEST(UnitInvariance, AFastMechanismFollowsTheSlowOneInItsOwnTime) {
  // Time x 1/20 (every spring's and latch's stiffness x 400, damping x 20):
  // rates near 1e3 rad/s, the small, fast mechanism a fixed bandwidth of
  // 2000 rad/s left 0.54 rad off. With the automatic bandwidth the angles
  // at t / 20 are the original's at t, up to the latch-up.
  const double s = 20;
  const std::vector<sim::Override> slow{{"regulator.v_max", "auto"}, {"run.t_end", "7.3"}, {"run.sample", "0.01"}};
  std::vector<sim::Override> fast{
      {"regulator.v_max", "auto"}, {"run.t_end", std::to_string(7.3 / s)}, {"run.sample", std::to_string(0.01 / s)}};
  for (int j = 1; j <= 8; ++j) {
    const std::string spring = "springs.j" + std::to_string(j) + ".";
    fast.push_back({spring + "stiffness", std::to_string(0.10 * s * s)});
    fast.push_back({spring + "damping", std::to_string(0.02 * s)});
    const std::string latch = "latches." + std::to_string(j - 1) + ".";
    fast.push_back({latch + "stiffness", std::to_string(1000 * s * s)});
    fast.push_back({latch + "damping", std::to_string(10 * s)});
  }
  const sim::SceneFile original = sim::read_builtin_scene("pantograph", slow);
  const sim::SceneFile quick = sim::read_builtin_scene("pantograph", fast);
  const sim::RunResult base = sim::simulate(original.scene, original.scene.run);
  const sim::RunResult run = sim::simulate(quick.scene, quick.scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  ASSERT_EQ(run.trajectory.samples.size(), base.trajectory.samples.size());
  ASSERT_TRUE(run.closure && base.closure);
  EXPECT_NEAR(run.closure->rate, s * base.closure->rate, 1e-9 * s * base.closure->rate);
  EXPECT_LT(test::largest_angle_difference(original.scene.model, run, base), 1e-7);
}

}  // namespace
}  // namespace unfurl
