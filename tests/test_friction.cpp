// Hinge friction against closed forms: a torsion oscillator under Coulomb
// friction loses the same amplitude every half cycle (2 T_c / k) and keeps
// its period; under viscous friction it decays exponentially. The work
// friction, dampers and latches dissipate closes the energy balance.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

// A disc of inertia I = 1 kg m^2 on a hinge about x with a torsion spring
// k = 1 N m/rad (omega = 1 rad/s), released at rest at `amplitude`.
std::string oscillator_text(const std::string& friction, double amplitude) {
  return R"(
name: oscillator
bodies:
  - name: disc
    parent: base
    mass: 1.0
    inertia: [1.0, 0.5, 0.5]
    joint: {name: hinge, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
springs:
  - {joint: hinge, stiffness: 1.0, free_position: 0}
friction:
  - )" + friction + R"(
initial:
  q: {hinge: )" + std::to_string(amplitude) + R"(}
run: {t_end: 12, sample: 0.001, rtol: 1.0e-10, atol: 1.0e-12}
)";
}

sim::Scene oscillator(const std::string& friction, double amplitude) {
  return sim::load_scene_text(oscillator_text(friction, amplitude), "oscillator");
}

struct Turn {
  double t, q;
};

// The turning points (dq changes sign), refined by the parabola through the
// three samples around each.
std::vector<Turn> turning_points(const sim::Trajectory& tr) {
  std::vector<Turn> turns;
  for (std::size_t k = 1; k + 1 < tr.samples.size(); ++k) {
    const double a = tr.samples[k - 1].y[0], b = tr.samples[k].y[0], c = tr.samples[k + 1].y[0];
    if ((b - a) * (c - b) >= 0) continue;
    const double h = tr.samples[k].t - tr.samples[k - 1].t;
    const double curvature = a - 2 * b + c;
    const double s = 0.5 * (a - c) / curvature;  // offset from sample k, in samples
    turns.push_back({tr.samples[k].t + s * h, b - 0.25 * (a - c) * s});
  }
  return turns;
}

TEST(Friction, CoulombTakesTheSameAmplitudeEveryHalfCycle) {
  // Each half cycle is a harmonic arc about +-T_c/k: the amplitude falls by
  // 2 T_c / k = 0.1 rad, and every half period is pi / omega.
  const double Tc = 0.05, A0 = 1.0;
  const sim::Scene scene = oscillator("{joint: hinge, coulomb: 0.05, velocity_scale: 1.0e-5}", A0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const std::vector<Turn> turns = turning_points(run.trajectory);
  ASSERT_GE(turns.size(), 3u);  // 1.0 -> -0.9 -> 0.8 -> -0.7 in 12 s
  for (std::size_t n = 0; n < turns.size() && n < 3; ++n) {
    const double expected = (A0 - 2 * Tc * (n + 1)) * (n % 2 == 0 ? -1 : 1);
    EXPECT_NEAR(turns[n].q, expected, 1e-6) << "turn " << n;
    EXPECT_NEAR(turns[n].t, M_PI * (n + 1), 1e-4) << "turn " << n;  // the tanh ramp lags by ~3e-5 s
  }
}

TEST(Friction, ViscousDecaysExponentially) {
  // I q'' + c q' + k q = 0 with c = 0.1: q = A e^(-zeta t) (cos w_d t + zeta/w_d sin w_d t).
  const double c = 0.1, zeta = c / 2, wd = std::sqrt(1 - zeta * zeta);
  const sim::Scene scene = oscillator("{joint: hinge, viscous: 0.1}", 1.0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    const double exact = std::exp(-zeta * s.t) * (std::cos(wd * s.t) + zeta / wd * std::sin(wd * s.t));
    worst = std::max(worst, std::abs(s.y[0] - exact));
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(Friction, DissipatedWorkClosesTheEnergyBalance) {
  // Coulomb and viscous together: the mechanical energy falls, the work
  // dissipated rises, and their sum stays at the initial energy.
  const sim::Scene scene = oscillator("{joint: hinge, coulomb: 0.03, viscous: 0.05, velocity_scale: 1.0e-3}", 1.0);
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.total();
  EXPECT_NEAR(E0, 0.5, 1e-12);
  double previous = 0, worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    EXPECT_GE(s.energy.dissipated, previous - 1e-15);
    previous = s.energy.dissipated;
    worst = std::max(worst, std::abs(s.energy.balance() - E0));
  }
  EXPECT_GT(previous, 0.4 * E0);  // most of it is gone by t = 12 s
  EXPECT_LT(worst, 1e-7 * E0);
}

TEST(Friction, LoadsReportTheFrictionTorque) {
  const sim::Scene scene = oscillator("{joint: hinge, coulomb: 0.2, viscous: 0.5, velocity_scale: 0.01}", 0.5);
  sim::Dynamics dynamics(scene);
  std::vector<double> y = dynamics.initial_state();
  y[1] = 0.02;  // p = I dq: dq = 0.02 rad/s, twice the velocity scale
  sim::Loads loads;
  ASSERT_TRUE(dynamics.loads(0, y.data(), loads));
  const double expected = -0.2 * std::tanh(2.0) - 0.5 * 0.02;
  const std::vector<sim::LoadColumn>& columns = dynamics.load_columns();
  EXPECT_NEAR(test::load_of(columns, loads, "friction_torque.hinge"), expected, 1e-14);
  EXPECT_NEAR(dynamics.dissipation(y.data(), std::vector<double>{0.02}.data()), -expected * 0.02, 1e-15);
  // The reaction's component about the hinge is the sum of the element torques.
  EXPECT_NEAR(
      loads.reaction[0][3],
      test::load_of(columns, loads, "spring_torque.hinge") + test::load_of(columns, loads, "friction_torque.hinge"),
      1e-12);
}

TEST(Friction, PantographBalancesEnergyWithItsLatches) {
  // The latches' damping takes energy out at each engagement: the balance
  // (mechanical energy + dissipated work) holds through all of them.
  const sim::Scene scene = test::scene_file("pantograph");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.balance();
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) worst = std::max(worst, std::abs(s.energy.balance() - E0));
  EXPECT_GT(run.trajectory.samples.back().energy.dissipated, 0.5 * E0);
  EXPECT_LT(worst, 1e-3 * E0);
}

TEST(Friction, SceneErrorsNameTheField) {
  const auto error_of = [](const std::string& entry) { return test::scene_error(oscillator_text(entry, 0.5)); };
  EXPECT_NE(error_of("{joint: hinge, coulomb: 0.1, velocity_scale: 0}").find("friction[0].velocity_scale"),
            std::string::npos);
  EXPECT_NE(error_of("{joint: hinge, coulomb: -0.1}").find("friction[0].coulomb"), std::string::npos);
  EXPECT_NE(error_of("{joint: hinge}").find("give coulomb, viscous or both"), std::string::npos);
  EXPECT_NE(error_of("{joint: elbow, coulomb: 0.1}").find("unknown joint 'elbow'"), std::string::npos);
}

}  // namespace
}  // namespace unfurl
