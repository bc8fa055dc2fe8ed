// Point-to-point spring-dampers and cables against closed forms (a slider
// on a spring oscillates at sqrt(k/m); a cable is slack, then taut for half
// a period), and the invariants: energy conserved with the springs' own
// energy, and balanced by the dissipated work when they damp.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

// A 2 kg block on a slider along x, tied to the base's origin by a point
// spring of k = 8 N/m (omega = 2 rad/s) and rest length 1 m.
sim::Scene slider(const std::string& spring_extra, double x0, double v0) {
  return sim::load_scene_text(R"(
name: slider
bodies:
  - name: block
    parent: base
    mass: 2.0
    inertia: [0.1, 0.1, 0.1]
    joint: {name: x, type: prismatic, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
point_springs:
  - {name: tie, body_a: base, point_a: [0, 0, 0], body_b: block, point_b: [0, 0, 0], stiffness: 8, rest_length: 1.0)" +
                                  spring_extra + R"(}
initial: {q: {x: )" + std::to_string(x0) +
                                  R"(}, dq: {x: )" + std::to_string(v0) + R"(}}
run: {t_end: 5, sample: 0.005, rtol: 1.0e-10, atol: 1.0e-12}
)",
                              "slider");
}

TEST(PointSprings, SliderOscillatesAtSqrtKOverM) {
  const sim::Scene scene = slider("", 1.5, 0.0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples)
    worst = std::max(worst, std::abs(s.y[0] - (1 + 0.5 * std::cos(2 * s.t))));
  EXPECT_LT(worst, 1e-7);
  // Its tension, in the loads: k (x - 1).
  const sim::Sample& s = run.trajectory.samples[100];
  ASSERT_EQ(s.loads.element.size(), 1u);
  EXPECT_NEAR(test::load_of(run.trajectory.load_columns, s.loads, "tension.tie"), 8 * (s.y[0] - 1), 1e-9);
}

TEST(PointSprings, CableIsSlackThenTautForHalfAPeriod) {
  // From x = 0.5 at 1 m/s: free flight to x = 1 (t = 0.5 s), half a period
  // of the spring (pi/2 s, out to 1.5 m), then free flight back at 1 m/s
  // (until x = -1, where the cable goes taut on the other side).
  const sim::Scene scene = slider(", tension_only: true", 0.5, 1.0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double t_back = 0.5 + M_PI / 2;
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    if (s.t > t_back + 1.9) break;
    double x = 0;
    if (s.t <= 0.5)
      x = 0.5 + s.t;
    else if (s.t <= t_back)
      x = 1 + 0.5 * std::sin(2 * (s.t - 0.5));
    else
      x = 1 - (s.t - t_back);
    worst = std::max(worst, std::abs(s.y[0] - x));
    if (std::abs(s.y[0]) < 1) {
      EXPECT_EQ(test::load_of(run.trajectory.load_columns, s.loads, "tension.tie"), 0.0) << s.t;
    }
  }
  EXPECT_LT(worst, 1e-6);
}

// Two links swinging under gravity about skew axes, a spring-damper from
// a point on the base to the second link and one between the two links,
// at points off their axes: every body frame, lever arm and velocity term.
sim::Scene linked_pendulum(double damping) {
  const std::string c = std::to_string(damping);
  return sim::load_scene_text(R"(
name: linked
gravity: [0, 0, -9.81]
bodies:
  - name: upper
    parent: base
    mass: 1.3
    com: [0.2, 0.0, -0.4]
    inertia: [0.05, 0.06, 0.02]
    joint: {name: j1, type: revolute, axis: [1, 0.3, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: lower
    parent: upper
    mass: 0.8
    com: [0.0, 0.1, -0.3]
    inertia: [0.03, 0.02, 0.04]
    joint: {name: j2, type: revolute, axis: [0.2, 1, 0.1], parent_point: [0.1, 0, -0.8], child_point: [0, 0, 0]}
point_springs:
  - {name: stay, body_a: base, point_a: [0.5, 0.4, 0.2], body_b: lower, point_b: [0.05, 0.1, -0.5], stiffness: 40,
     rest_length: 0.9, damping: )" +
                                  c + R"(}
  - {name: link, body_a: upper, point_a: [0.1, 0.2, -0.2], body_b: lower, point_b: [-0.1, 0, -0.4], stiffness: 25,
     rest_length: 0.3, damping: )" +
                                  c + R"(}
initial: {q: {j1: 0.7, j2: -0.5}, dq: {j1: 1.0}}
run: {t_end: 4, sample: 0.01, rtol: 1.0e-12, atol: 1.0e-14}
)",
                              "linked");
}

// The largest kinetic energy of a run: the scale of its energy errors (the
// total is small here, its parts cancel).
double kinetic_scale(const sim::Trajectory& tr) {
  double K = 0;
  for (const sim::Sample& s : tr.samples) K = std::max(K, s.energy.kinetic);
  return K;
}

TEST(PointSprings, EnergyIsConservedWithTheSpringsEnergy) {
  // A force inconsistent with the springs' energy (a lever arm or frame
  // wrong) would drift by joules; the integration error at rtol 1e-12 is
  // about 4e-9 J (2e-7 J at 1e-10, 1e-5 J at 1e-8).
  const sim::Scene scene = linked_pendulum(0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.total();
  double worst = 0, swing = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    worst = std::max(worst, std::abs(s.energy.total() - E0));
    swing = std::max(swing, std::abs(s.energy.springs - run.trajectory.samples.front().energy.springs));
  }
  EXPECT_GT(swing, 0.1);  // the springs do store and give back energy
  EXPECT_LT(worst, 1e-8 * kinetic_scale(run.trajectory));
}

TEST(PointSprings, DampingIsBalancedByTheDissipatedWork) {
  const sim::Scene scene = linked_pendulum(0.8);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.total();
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) worst = std::max(worst, std::abs(s.energy.balance() - E0));
  EXPECT_GT(run.trajectory.samples.back().energy.dissipated, 0.1);
  EXPECT_LT(worst, 1e-8 * kinetic_scale(run.trajectory));
}

TEST(PointSprings, SceneErrorsNameTheField) {
  const auto error_of = [](const std::string& extra) {
    return test::scene_error(R"(
bodies:
  - {name: block, parent: base, mass: 1, inertia: [1, 1, 1],
     joint: {name: x, type: prismatic, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
point_springs:
  - )" + extra + "\n");
  };
  const std::string same = error_of("{body_a: block, body_b: block, point_b: [1, 0, 0], stiffness: 1, rest_length: 1}");
  EXPECT_NE(same.find("point_springs[0].body_b: both ends are on one body"), std::string::npos) << same;
  const std::string unknown = error_of("{body_a: base, body_b: panel, stiffness: 1, rest_length: 1}");
  EXPECT_NE(unknown.find("point_springs[0].body_b: unknown body 'panel'"), std::string::npos) << unknown;
  const std::string coincide = error_of("{body_a: base, body_b: block, stiffness: 1, rest_length: 1}");
  EXPECT_NE(coincide.find("coincide"), std::string::npos) << coincide;
  const std::string negative =
      error_of("{body_a: base, body_b: block, point_b: [1, 0, 0], stiffness: 1, rest_length: -1}");
  EXPECT_NE(negative.find("point_springs[0].rest_length"), std::string::npos) << negative;
}

}  // namespace
}  // namespace unfurl
