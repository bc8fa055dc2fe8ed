// Torque margins against closed forms: a hinge driven by a spring against
// Coulomb friction has MoF(q) = k (q_free - q) / (f_F c) over its travel,
// smallest at its latch; a harness cable that tightens as it deploys takes
// the margin below the required factor, and the run says so; the scene's
// own factors are used.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/sim/torque_margin.hpp"

namespace unfurl {
namespace {

// A 2 kg panel on a hinge about x, a spring of 2 N m/rad relaxed at 1 rad
// driving it from 0 to its latch at 0.8 rad, Coulomb friction 0.05 N m.
std::string hinge(const std::string& extra) {
  return R"(
name: hinge
bodies:
  - name: panel
    parent: base
    mass: 2.0
    com: [0, 0.5, 0]
    inertia: [0.2, 0.1, 0.25]
    joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
springs:
  - {joint: h, stiffness: 2.0, free_position: 1.0}
friction:
  - {joint: h, coulomb: 0.05, velocity_scale: 1.0e-6}
latches:
  - {joint: h, position: 0.8, stiffness: 1000, damping: 10}
run: {t_end: 3, rtol: 1.0e-10, atol: 1.0e-12, sample: 0.005}
)" + extra;
}

TEST(TorqueMargin, SpringAgainstFrictionMatchesItsClosedForm) {
  const sim::Scene scene = sim::load_scene_text(hinge(""), "hinge");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.trajectory.events.size(), 1u);
  const std::vector<sim::JointTorqueMargin> m = sim::torque_margins(scene, run.trajectory);
  ASSERT_EQ(m.size(), 1u);
  const auto closed_form = [](double q) { return 2.0 * (1.0 - q) / (3.0 * 0.05); };
  ASSERT_EQ(m[0].quasi_static.size(), 101u);
  for (const sim::TorqueMarginPoint& p : m[0].quasi_static) EXPECT_NEAR(p.factor, closed_form(p.q), 1e-9);
  EXPECT_NEAR(m[0].quasi_static[m[0].worst_quasi_static].q, 0.8, 1e-12);
  EXPECT_NEAR(m[0].worst(), closed_form(0.8), 1e-9);  // 2.667
  ASSERT_GT(m[0].run.size(), 10u);
  for (const sim::TorqueMarginPoint& p : m[0].run) {
    EXPECT_LT(p.t, run.trajectory.events[0].t);
    // Viscous 0: friction is the Coulomb torque alone.
    EXPECT_NEAR(p.factor, closed_form(p.q), 1e-9) << p.t;
  }
  const sim::RunSummary s = sim::summarize(scene, run);
  EXPECT_TRUE(s.torque_margins_pass());
}

// The workbench cancels a superseded run's summary: a cancel set before it
// starts stops it before any joint's margins; one never set changes nothing.
TEST(TorqueMargin, ACancelStopsItAndAnUnsetOneChangesNothing) {
  const sim::Scene scene = sim::load_scene_text(hinge(""), "hinge");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(sim::torque_margins(scene, run.trajectory, &cancel).empty());  // cancelled before it started
  cancel = false;
  const std::vector<sim::JointTorqueMargin> with = sim::torque_margins(scene, run.trajectory, &cancel);
  const std::vector<sim::JointTorqueMargin> without = sim::torque_margins(scene, run.trajectory);
  ASSERT_EQ(with[0].quasi_static.size(), 101u);
  EXPECT_EQ(with[0].worst(), without[0].worst());
  EXPECT_EQ(with[0].run.size(), without[0].run.size());
}

TEST(TorqueMargin, AHarnessCableThatTightensFailsItAndTheRunSaysSo) {
  // A cable from the base to the panel's tip, slack when stowed, taut from
  // about half the travel, pulling back harder the further it deploys.
  const std::string cable = R"(
point_springs:
  - {name: harness, body_a: base, point_a: [0, 1.0, -0.05], body_b: panel, point_b: [0, 1.0, 0],
     stiffness: 1, rest_length: 0.4, tension_only: true}
)";
  const sim::Scene scene = sim::load_scene_text(hinge(cable), "hinge");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const sim::RunSummary s = sim::summarize(scene, run);
  ASSERT_EQ(s.torque_margins.size(), 1u);
  EXPECT_FALSE(s.torque_margins_pass());
  const sim::JointTorqueMargin& m = s.torque_margins[0];
  EXPECT_LT(m.worst(), 2.0);
  // Quasi-statically the harness holds it back only where the cable is taut
  // (the tip (1 - cos q, sin q + 0.05) from its anchor: taut beyond 0.352).
  for (const sim::TorqueMarginPoint& p : m.quasi_static) {
    if (p.q < 0.34) {
      EXPECT_EQ(p.harness, 0.0) << p.q;
    } else if (p.q > 0.37) {
      EXPECT_GT(p.harness, 0.0) << p.q;
    }
  }
  // A scene that requires less passes.
  const sim::Scene lenient = sim::load_scene_text(hinge(cable + "torque_margin: {required: 0.5, harness: 1}\n"), "h");
  EXPECT_TRUE(sim::summarize(lenient, sim::simulate(lenient, lenient.run)).torque_margins_pass());
}

}  // namespace
}  // namespace unfurl
