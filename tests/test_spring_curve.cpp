// Measured spring curves (monotone cubic through test points) and latches
// with free play: the curve's own properties, a linear table against the
// linear spring, energy and its balance, and what backlash does to the
// latch's bite.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/elements/spring_curve.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

TEST(SpringCurve, PassesThroughItsPointsWithoutOvershoot) {
  // A torque that falls steeply, then flattens: a spline through these
  // would dip below the flat part; the monotone cubic does not.
  const sim::SpringCurve curve({0, 0.5, 1.0, 1.5, 2.0}, {1.0, 0.9, 0.2, 0.1, 0.1});
  for (std::size_t k = 0; k < curve.angles().size(); ++k)
    EXPECT_DOUBLE_EQ(curve.torque(curve.angles()[k]), curve.torques()[k]);
  double previous = curve.torque(0);
  for (double q = 0; q <= 2.0; q += 1e-3) {
    const double tau = curve.torque(q);
    EXPECT_LE(tau, previous + 1e-15) << q;  // never rises
    EXPECT_GE(tau, 0.1 - 1e-15) << q;       // never below the flat end
    previous = tau;
  }
}

TEST(SpringCurve, SlopeAndEnergyAreItsDerivativeAndIntegral) {
  const sim::SpringCurve curve({-1.0, -0.2, 0.4, 1.3}, {0.8, 0.5, 0.1, -0.3});
  for (double q = -1.5; q <= 1.8; q += 0.0137) {
    const double h = 1e-6;
    EXPECT_NEAR(curve.slope(q), (curve.torque(q + h) - curve.torque(q - h)) / (2 * h), 1e-6) << q;
    EXPECT_NEAR(-curve.torque(q), (curve.energy(q + h) - curve.energy(q - h)) / (2 * h), 1e-6) << q;
  }
  // Beyond the table: the end slopes' straight lines.
  EXPECT_NEAR(curve.torque(2.3) - curve.torque(1.3), curve.slope(1.3) * 1.0, 1e-12);
}

std::string disc(const std::string& spring, const std::string& latch) {
  return R"(
name: disc
bodies:
  - name: disc
    parent: base
    mass: 1.0
    inertia: [0.5, 0.5, 0.5]
    joint: {name: hinge, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
springs:
  - )" + spring + "\n" + latch + R"(
initial: {q: {hinge: -1.5}}
run: {t_end: 6, sample: 0.002, rtol: 1.0e-10, atol: 1.0e-12}
)";
}

TEST(SpringCurve, ALinearTableIsTheLinearSpring) {
  // Two points of tau = -0.3 (q - 0.4): the same run as stiffness 0.3 and
  // free position 0.4, to the integrator's tolerance.
  const sim::Scene table =
      sim::load_scene_text(disc("{joint: hinge, table: [[-2, 0.72], [2, -0.48]], damping: 0.01}", ""), "t");
  const sim::Scene linear =
      sim::load_scene_text(disc("{joint: hinge, stiffness: 0.3, free_position: 0.4, damping: 0.01}", ""), "l");
  const sim::RunResult a = sim::simulate(table, table.run), b = sim::simulate(linear, linear.run);
  ASSERT_EQ(a.status, sim::RunStatus::finished);
  ASSERT_EQ(a.trajectory.samples.size(), b.trajectory.samples.size());
  for (std::size_t k = 0; k < a.trajectory.samples.size(); ++k) {
    EXPECT_NEAR(a.trajectory.samples[k].y[0], b.trajectory.samples[k].y[0], 1e-8);
    // The curve's energy is zero at its first point, the line's at its free
    // position: equal up to that constant.
    EXPECT_NEAR(a.trajectory.samples[k].energy.total() - a.trajectory.samples[0].energy.total(),
                b.trajectory.samples[k].energy.total() - b.trajectory.samples[0].energy.total(), 1e-9);
  }
}

TEST(SpringCurve, MeasuredCurveConservesEnergy) {
  const sim::Scene scene = sim::load_scene_text(
      disc("{joint: hinge, table: [[-1.6, 0.35], [-0.8, 0.26], [0, 0.2], [0.8, 0.05], [1.6, -0.3]]}", ""), "curve");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.total();
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) worst = std::max(worst, std::abs(s.energy.total() - E0));
  EXPECT_LT(worst, 1e-8);
}

// The disc driven by a spring through a latch at q = 0, with and without
// free play.
sim::RunResult latch_run(double free_play) {
  const sim::Scene scene =
      sim::load_scene_text(disc("{joint: hinge, stiffness: 0.2, free_position: 1.5}",
                                "latches:\n  - {joint: hinge, position: 0, stiffness: 500, damping: 2, free_play: " +
                                    std::to_string(free_play) + "}"),
                           "latch");
  return sim::simulate(scene, scene.run);
}

TEST(LatchFreePlay, TheJointRattlesFreelyThenBitesHarder) {
  const sim::RunResult tight = latch_run(0), loose = latch_run(0.1);
  ASSERT_EQ(tight.status, sim::RunStatus::finished);
  ASSERT_EQ(loose.status, sim::RunStatus::finished);
  ASSERT_EQ(loose.trajectory.events.size(), 1u);
  // Inside the free play the latch carries nothing.
  int inside = 0;
  for (const sim::Sample& s : loose.trajectory.samples) {
    if (s.t <= loose.trajectory.events[0].t || std::abs(s.y[0]) >= 0.05) continue;
    ++inside;
    EXPECT_EQ(test::load_of(loose.trajectory.load_columns, s.loads, "latch_torque.hinge"), 0.0) << s.t;
  }
  EXPECT_GT(inside, 0);
  // It bites at the edge of the play, faster than a tight latch catches:
  // a larger peak torque.
  EXPECT_GT(loose.peaks.latch_torque[0].value, tight.peaks.latch_torque[0].value);
  // The balance holds with the latch's work taken out, less tightly than
  // for smooth elements (1e-8): the bite is a jump in the damping torque
  // that no event locates, and the dissipation's quadrature straddles it
  // (measured 3.9e-6 J of 0.9 J at rtol 1e-10).
  const double E0 = loose.trajectory.samples.front().energy.total();
  double worst = 0;
  for (const sim::Sample& s : loose.trajectory.samples) worst = std::max(worst, std::abs(s.energy.balance() - E0));
  EXPECT_GT(loose.trajectory.samples.back().energy.dissipated, 0.1 * E0);
  EXPECT_LT(worst, 1e-5 * E0);
}

TEST(SpringCurve, SceneErrorsNameTheField) {
  const auto error_of = [](const std::string& spring) { return test::scene_error(disc(spring, "")); };
  const std::string order = error_of("{joint: hinge, table: [[0, 1], [1, 0.5], [0.5, 0.2]]}");
  EXPECT_NE(order.find("springs[0].table[2]: the angles must increase"), std::string::npos) << order;
  const std::string both = error_of("{joint: hinge, stiffness: 1, table: [[0, 1], [1, 0.5]]}");
  EXPECT_NE(both.find("springs[0].stiffness: a spring with a table"), std::string::npos) << both;
  const std::string one = error_of("{joint: hinge, table: [[0, 1]]}");
  EXPECT_NE(one.find("springs[0].table: expected a list of at least two"), std::string::npos) << one;
  const std::string pair = error_of("{joint: hinge, table: [[0, 1, 2], [1, 0.5]]}");
  EXPECT_NE(pair.find("springs[0].table[0]: expected [angle, torque]"), std::string::npos) << pair;
}

}  // namespace
}  // namespace unfurl
