// Latch events: simultaneous latches in one restart, each at its own root; a
// root exactly at the end of the run; a latch engaged at t = 0; a graze that
// begins and ends inside one step; the step statistics around restarts.
//
// The scenes are torsion oscillators without gravity: a body turning about
// x through its centre, I = 0.5 kg m^2, spring k, released at rest from q0,
// so q(t) = q0 cos(w t), w = sqrt(k / I), crossing q = 0 at t = pi / (2 w).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "unfurl/sim/number_text.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

std::string oscillator_body(const std::string& name) {
  return "  - name: " + name +
         "\n    parent: base\n    mass: 1.0\n    inertia: [0.5, 0.5, 0.5]\n"
         "    joint: {name: " + name + ", type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}\n";
}

// Oscillators (name, stiffness, q0, latch position), latched with
// k_L = 1000, c_L = 10.
struct Oscillator {
  std::string name;
  double stiffness, q0, latch_at;
};

sim::Scene oscillators(const std::vector<Oscillator>& list, const std::string& run) {
  std::string text = "name: oscillators\nbodies:\n";
  for (const Oscillator& o : list) text += oscillator_body(o.name);
  text += "springs:\n";
  for (const Oscillator& o : list)
    text += "  - {joint: " + o.name + ", stiffness: " + sim::format_number(o.stiffness) + ", free_position: 0}\n";
  text += "latches:\n";
  for (const Oscillator& o : list)
    text +=
        "  - {joint: " + o.name + ", position: " + sim::format_number(o.latch_at) + ", stiffness: 1000, damping: 10}\n";
  text += "initial:\n  q: {";
  for (std::size_t k = 0; k < list.size(); ++k)
    text += (k ? ", " : "") + list[k].name + ": " + sim::format_number(list[k].q0);
  text += "}\nrun: " + run + "\n";
  return sim::load_scene_text(text, "oscillators");
}

double crossing_time(double stiffness) { return M_PI / 2 * std::sqrt(0.5 / stiffness); }

TEST(Events, NearlySimultaneousLatchesTakeOneRestartEachAtItsOwnRoot) {
  // Stiffnesses 1e-7 apart: the roots lie 7.9e-8 s apart, inside the
  // default 1e-6 s window.
  const double k1 = 2.0, k2 = 2.0 * (1 + 2e-7);
  for (const char* integrator : {"cvode-bdf", "arkode-erk", "arkode-dirk", "rk4"}) {
    const sim::Scene scene = oscillators(
        {{"a", k1, 1.0, 0.0}, {"b", k2, 1.0, 0.0}},
        std::string("{t_end: 1.5, rtol: 1.0e-11, atol: 1.0e-13, dt: 1.0e-4, integrator: ") + integrator + "}");
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << integrator << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.events.size(), 2u) << integrator;
    EXPECT_EQ(run.stats.restarts, 1) << integrator;
    const double tolerance = std::string(integrator) == "rk4" ? 1e-9 : 1e-10;
    for (const sim::LatchEvent& e : run.trajectory.events)
      EXPECT_NEAR(e.t, crossing_time(e.latch == 0 ? k1 : k2), tolerance) << integrator << " latch " << e.latch;
    EXPECT_LT(run.trajectory.events[0].t, run.trajectory.events[1].t) << "in the order they happened";
  }
}

TEST(Events, PantographsEightLatchesTakeOneRestart) {
  const sim::Scene scene = test::scene_file("pantograph");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_EQ(run.trajectory.events.size(), 8u);
  EXPECT_EQ(run.stats.restarts, 1);
}

TEST(Events, LatchesFartherApartThanTheWindowTakeARestartEach) {
  const double k1 = 2.0, k2 = 2.0 * (1 + 1e-4);  // 7.9e-5 s apart
  const sim::Scene scene =
      oscillators({{"a", k1, 1.0, 0.0}, {"b", k2, 1.0, 0.0}}, "{t_end: 1.5, rtol: 1.0e-11, atol: 1.0e-13}");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.trajectory.events.size(), 2u);
  EXPECT_EQ(run.stats.restarts, 2);
  for (const sim::LatchEvent& e : run.trajectory.events) EXPECT_NEAR(e.t, crossing_time(e.latch == 0 ? k1 : k2), 1e-10);
}

TEST(Events, RootJustBeforeTheEndIsFoundAndTheRunEndsCleanly) {
  const double t_cross = crossing_time(2.0);
  for (const char* integrator : {"cvode-bdf", "arkode-erk", "rk4"}) {
    const sim::Scene scene = oscillators({{"a", 2.0, 1.0, 0.0}}, "{t_end: " + sim::format_number(t_cross + 1e-12) +
                                                                     ", rtol: 1.0e-11, atol: 1.0e-13, dt: 1.0e-3, "
                                                                     "sample: 0.01, integrator: " +
                                                                     integrator + "}");
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << integrator << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.events.size(), 1u) << integrator;
    EXPECT_NEAR(run.trajectory.events[0].t, t_cross, 1e-9) << integrator;
    EXPECT_EQ(run.trajectory.samples.back().t, scene.run.t_end) << integrator;
    const auto& s = run.trajectory.samples;
    EXPECT_LT(s[s.size() - 2].t, s.back().t) << integrator << ": the last sample is recorded once";
  }
}

TEST(Events, RootExactlyAtTheEndEndsTheRunCleanly) {
  // t_end is the crossing time to the last digit: whether the last step
  // sees the root or not, the run ends at t_end with one last sample, and a
  // latch it engages is engaged at t_end.
  const double t_cross = crossing_time(2.0);
  for (const char* integrator : {"cvode-bdf", "arkode-erk", "rk4"}) {
    const sim::Scene scene = oscillators({{"a", 2.0, 1.0, 0.0}}, "{t_end: " + sim::format_number(t_cross) +
                                                                     ", rtol: 1.0e-11, atol: 1.0e-13, dt: 1.0e-3, "
                                                                     "integrator: " +
                                                                     integrator + "}");
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << integrator << ": " << sim::describe(run.failure);
    EXPECT_LE(run.trajectory.events.size(), 1u);
    for (const sim::LatchEvent& e : run.trajectory.events) EXPECT_NEAR(e.t, t_cross, 1e-9) << integrator;
    EXPECT_EQ(run.trajectory.samples.back().t, scene.run.t_end);
    EXPECT_LT(std::abs(run.trajectory.samples.back().y[0]), 1e-8) << integrator << ": at the crossing";
  }
}

TEST(Events, LatchAtTheStartIsEngagedFromTheStartAndHolds) {
  // The joint starts at its latch position with the spring pulling it away
  // (free position 1): caught at t = 0, it sits at the static deflection.
  sim::Scene scene = oscillators({{"a", 2.0, 0.0, 0.0}}, "{t_end: 5, rtol: 1.0e-10, atol: 1.0e-12}");
  auto spring = std::make_shared<sim::JointSpring>(*scene.elements_of<sim::JointSpring>()[0]);
  spring->free_position = 1.0;
  scene.elements[0] = spring;  // the scene's first element is its spring
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  ASSERT_EQ(run.trajectory.events.size(), 1u);
  EXPECT_EQ(run.trajectory.events[0].t, 0.0);
  EXPECT_EQ(run.stats.restarts, 0);
  // k (1 - q) = k_L q at rest: q = k / (k + k_L).
  EXPECT_NEAR(run.trajectory.samples.back().y[0], 2.0 / 1002.0, 1e-6);
}

TEST(Events, GrazeInsideOneStepIsNotMissed) {
  // Amplitude 1, latch at -0.99999: the joint dips past the latch for 4.5 ms
  // around its turning point, inside one step at these tolerances, so the
  // switching function has the same sign at both ends of the step. Near
  // the turning point the crossing time moves by sqrt of an error in q:
  // rtol 1e-5 puts it within a few milliseconds.
  const double q_latch = -0.99999;
  const double t_graze = (M_PI - std::acos(-q_latch)) / std::sqrt(2.0 / 0.5);
  for (const char* integrator : {"cvode-bdf", "arkode-erk", "rk4"}) {
    const sim::Scene scene =
        oscillators({{"a", 2.0, 1.0, q_latch}},
                    std::string("{t_end: 2, rtol: 1.0e-5, atol: 1.0e-7, dt: 0.05, integrator: ") + integrator + "}");
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << integrator << ": " << sim::describe(run.failure);
    ASSERT_EQ(run.trajectory.events.size(), 1u) << integrator << ": the graze was missed";
    EXPECT_EQ(run.stats.grazes, 1) << integrator << ": found by the graze check, not the root finding";
    EXPECT_NEAR(run.trajectory.events[0].t, t_graze, 2e-3) << integrator;
  }
}

TEST(Events, MinimumStepIsTakenAwayFromRestarts) {
  // After every restart the step grows from a tiny first one: those are
  // counted apart, so min_step says what the dynamics needed.
  const sim::Scene scene = test::scene_file("zfold");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.stats.restarts, 4);
  EXPECT_GT(run.stats.min_step, 10 * run.stats.min_step_after_restart);
  EXPECT_GT(run.stats.min_step, 1e-8);
}

}  // namespace
}  // namespace unfurl
