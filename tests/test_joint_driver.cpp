// Drivers (joint_driver.hpp): the profiles against their closed forms, the
// drive torque of a driven pendulum and of a driven hub carrying a sprung
// link against Lagrange's equations, the passive link's motion against the
// same equations integrated apart, the energy balance with the drivers'
// work, a driven crank closing a loop, and the scene file's rules.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl {
namespace {

const char* kRod = R"(
name: driven_rod
gravity: [0, 0, -9.81]
bodies:
  - name: rod
    parent: base
    mass: 2.0
    com: [0, 0, -0.5]
    inertia: [0.1, 0.1, 0.02]
    joint: {name: hinge, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
drivers:
  - {joint: hinge, profile: move, amount: 1.5707963267948966, duration: 2, start: 0.5}
run: {t_end: 3, rtol: 1e-10, atol: 1e-12, sample: 0.01}
)";

// A hub driven about z carrying a link on a sprung hinge at its tip; no
// gravity. Hub: mass 3, arm a = 0.8, its centre of mass at a / 2. Link: mass
// m2 = 1.5, centre of mass b = 0.6 out, I2 = 0.05 about it; spring k = 20.
const char* kHubAndLink = R"(
name: hub_and_link
bodies:
  - name: hub
    parent: base
    mass: 3.0
    com: [0.4, 0, 0]
    inertia: [0.01, 0.2, 0.2]
    joint: {name: drive, type: revolute, axis: [0, 0, 1], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: link
    parent: hub
    mass: 1.5
    com: [0.6, 0, 0]
    inertia: [0.01, 0.05, 0.05]
    joint: {name: elbow, type: revolute, axis: [0, 0, 1], parent_point: [0.8, 0, 0], child_point: [0, 0, 0]}
springs:
  - {joint: elbow, stiffness: 20, free_position: 0, damping: 0}
drivers:
  - {joint: drive, profile: spin_up, amount: 4, duration: 3}
run: {t_end: 5, rtol: 1e-11, atol: 1e-13, sample: 0.01}
)";

constexpr double a = 0.8, m2 = 1.5, b = 0.6, I2 = 0.05, k = 20;
constexpr double I1 = 0.2 + 3.0 * 0.4 * 0.4;  // the hub about its axis

// The link's relative angle phi under the hub's prescribed theta(t):
// (m2 b^2 + I2) phi'' = -k phi - (m2 b^2 + I2 + m2 a b cos phi) theta''
//                       - m2 a b theta'^2 sin phi.
double link_acceleration(double phi, const sim::JointDriver::Motion& hub) {
  const double J = m2 * b * b + I2;
  return (-k * phi - (J + m2 * a * b * std::cos(phi)) * hub.acceleration -
          m2 * a * b * hub.rate * hub.rate * std::sin(phi)) /
         J;
}

// The hub's torque by Lagrange's equation for theta, at a state of the link.
double hub_torque(double phi, double phi_rate, const sim::JointDriver::Motion& hub) {
  const double phi_acc = link_acceleration(phi, hub), th = hub.rate, tha = hub.acceleration;
  return I1 * tha + I2 * (tha + phi_acc) +
         m2 * (a * a * tha + b * b * (tha + phi_acc) + a * b * (2 * tha + phi_acc) * std::cos(phi) -
               a * b * (2 * th + phi_rate) * phi_rate * std::sin(phi));
}

int column(const sim::Trajectory& tr, const std::string& name) {
  const int c = sim::find_load_column(tr.load_columns, name);
  EXPECT_GE(c, 0) << name;
  return c;
}

TEST(JointDriver, ProfilesAreTheirOwnIntegrals) {
  sim::JointDriver d(0);
  for (const auto profile : {sim::JointDriver::Profile::move, sim::JointDriver::Profile::spin_up}) {
    d.profile = profile;
    d.amount = 1.3;
    d.duration = 2;
    d.start = 0.5;
    const double h = 1e-5;
    for (double t = 0; t < 4; t += 0.173) {
      const auto m = d.at(t), before = d.at(t - h), after = d.at(t + h);
      EXPECT_NEAR((after.x - before.x) / (2 * h), m.rate, 1e-8) << t;
      EXPECT_NEAR((after.rate - before.rate) / (2 * h), m.acceleration, 1e-7) << t;
    }
    EXPECT_EQ(d.at(0.5).rate, 0);
    EXPECT_EQ(d.at(0.2).x, 0);
  }
  // Simo and Vu-Quoc's spin-up: theta = 6 t - 45 after 15 s.
  d.profile = sim::JointDriver::Profile::spin_up;
  d.amount = 6;
  d.duration = 15;
  d.start = 0;
  EXPECT_NEAR(d.at(20).x, 6 * 20 - 45, 1e-12);
  EXPECT_NEAR(d.at(7.5).x, 0.4 * (7.5 * 7.5 / 2 + std::pow(15 / (2 * M_PI), 2) * (std::cos(M_PI) - 1)), 1e-12);
  // A move ends where it was sent, at rest.
  d.profile = sim::JointDriver::Profile::move;
  EXPECT_NEAR(d.at(15).x, 6, 1e-15);
  EXPECT_EQ(d.at(15).rate, 0);
}

TEST(JointDriver, APendulumFollowsItsDriverAndTheTorqueIsInertiaPlusWeight) {
  const sim::Scene scene = sim::load_scene_text(kRod, "driven_rod");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const auto* driver = scene.elements_of<sim::JointDriver>().front();
  const int c = column(run.trajectory, "drive_torque.hinge");
  double worst_angle = 0, worst_torque = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    const sim::JointDriver::Motion m = driver->at(s.t);
    worst_angle = std::max(worst_angle, std::abs(s.y[0] - m.x));
    // tau = I_o theta'' + m g l sin(theta), I_o = 0.1 + 2 (0.5)^2.
    const double tau = 0.6 * m.acceleration + 2.0 * 9.81 * 0.5 * std::sin(s.y[0]);
    worst_torque = std::max(worst_torque, std::abs(s.loads.element[c] - tau));
  }
  // The driven angle is integrated with the rest of the state, to the
  // run's tolerance; the torque is exact at the state reached.
  EXPECT_LT(worst_angle, 1e-8);
  EXPECT_LT(worst_torque, 1e-10);
  // Held at 90 degrees after the move: the torque carries the weight's moment.
  EXPECT_NEAR(run.trajectory.samples.back().loads.element[c], 2.0 * 9.81 * 0.5, 1e-8);
  // Its work is the potential energy it lifted the rod by.
  EXPECT_NEAR(run.trajectory.samples.back().energy.driven, 2.0 * 9.81 * 0.5, 1e-8);
}

TEST(JointDriver, ADrivenHubMovesASprungLinkAsLagrangesEquationsSay) {
  const sim::Scene scene = sim::load_scene_text(kHubAndLink, "hub_and_link");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const auto* driver = scene.elements_of<sim::JointDriver>().front();
  const int drive = column(run.trajectory, "drive_torque.drive");
  const int elbow = scene.model.position_of(1).value;

  // The link's equation integrated apart: classical RK4, 1e-4 s.
  double phi = 0, phi_rate = 0, t = 0, worst_phi = 0, worst_torque = 0, largest_torque = 0;
  const double h = 1e-4;
  std::size_t next = 0;
  const auto& samples = run.trajectory.samples;
  while (next < samples.size()) {
    if (std::abs(samples[next].t - t) < 0.5 * h) {
      const sim::Sample& s = samples[next++];
      worst_phi = std::max(worst_phi, std::abs(s.y[elbow] - phi));
      // The torque at unfurl's own state, by Lagrange's equation for theta.
      const double tau = hub_torque(s.y[elbow], s.q_dot[elbow], driver->at(s.t));
      worst_torque = std::max(worst_torque, std::abs(s.loads.element[drive] - tau));
      largest_torque = std::max(largest_torque, std::abs(tau));
    }
    auto f = [&](double tt, double x, double v) {
      return std::array<double, 2>{v, link_acceleration(x, driver->at(tt))};
    };
    const auto k1 = f(t, phi, phi_rate);
    const auto k2 = f(t + h / 2, phi + h / 2 * k1[0], phi_rate + h / 2 * k1[1]);
    const auto k3 = f(t + h / 2, phi + h / 2 * k2[0], phi_rate + h / 2 * k2[1]);
    const auto k4 = f(t + h, phi + h * k3[0], phi_rate + h * k3[1]);
    phi += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    phi_rate += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    t += h;
  }
  EXPECT_GT(largest_torque, 1.0);
  EXPECT_LT(worst_phi, 1e-7);
  EXPECT_LT(worst_torque, 1e-8 * largest_torque);
  // The hub's angle is the driver's.
  EXPECT_NEAR(samples.back().y[0], driver->at(samples.back().t).x, 1e-8);
}

TEST(JointDriver, TheEnergyBalanceHoldsWithTheDriversWork) {
  sim::Scene scene = sim::load_scene_text(kHubAndLink, "hub_and_link", {{"springs.elbow.damping", "0.3"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double E0 = run.trajectory.samples.front().energy.balance();
  double drift = 0;
  for (const sim::Sample& s : run.trajectory.samples) drift = std::max(drift, std::abs(s.energy.balance() - E0));
  const sim::EnergyParts& end = run.trajectory.samples.back().energy;
  EXPECT_GT(end.driven, 10.0);
  EXPECT_GT(end.dissipated, 0.01);
  EXPECT_LT(drift, 1e-7 * end.driven);
}

TEST(JointDriver, ADrivenCrankTurnsAFourBarWithItsLoopClosed) {
  const sim::Scene scene = sim::load_builtin_scene(
      "fourbar", {{"drivers", "[{joint: crank_pivot, profile: spin_up, amount: 3, duration: 1}]"}, {"run.t_end", "3"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  EXPECT_LT(run.peaks.gap_m.value, 1e-9);
  const auto* driver = scene.elements_of<sim::JointDriver>().front();
  const sim::Sample& end = run.trajectory.samples.back();
  EXPECT_NEAR(end.y[0] - scene.q0[0], driver->at(end.t).x, 1e-7);
  double drift = 0;
  for (const sim::Sample& s : run.trajectory.samples)
    drift = std::max(drift, std::abs(s.energy.balance() - run.trajectory.samples.front().energy.balance()));
  EXPECT_LT(drift, 1e-6 * std::abs(end.energy.driven) + 1e-9);
}

// A motor on a free-floating bus swings an arm: its torque is internal, so
// the bus turns the other way and the system's momentum stays at zero.
TEST(JointDriver, AMotorOnAFreeBusKeepsTheMomentum) {
  const sim::Scene scene = sim::load_scene_text(R"(
name: bus_and_arm
base: {name: bus, free: true, mass: 50, com: [0, 0, 0], inertia: [5, 6, 7]}
bodies:
  - name: arm
    parent: bus
    mass: 4
    com: [0.5, 0, 0]
    inertia: [0.01, 0.1, 0.1]
    joint: {name: shoulder, type: revolute, axis: [0, 0, 1], parent_point: [0.6, 0, 0], child_point: [0, 0, 0]}
drivers:
  - {joint: shoulder, profile: move, amount: 2, duration: 3}
run: {t_end: 4, rtol: 1e-10, atol: 1e-12}
)",
                                                "bus_and_arm");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  double linear = 0, angular = 0, linear_scale = 0, angular_scale = 0, balance = 0;
  const double E0 = run.trajectory.samples.front().energy.balance();
  for (const sim::Sample& s : run.trajectory.samples) {
    linear = std::max(linear, s.momentum.linear.norm());
    angular = std::max(angular, s.momentum.angular.norm());
    linear_scale = std::max(linear_scale, s.momentum.linear_scale);
    angular_scale = std::max(angular_scale, s.momentum.angular_scale);
    balance = std::max(balance, std::abs(s.energy.balance() - E0));
  }
  EXPECT_GT(angular_scale, 1.0);
  EXPECT_LT(linear, 1e-10 * linear_scale);
  EXPECT_LT(angular, 1e-10 * angular_scale);
  // The arm's 2 rad, the bus's turn against it; at rest after the move,
  // every joule the motor put in taken out again.
  const sim::Sample& end = run.trajectory.samples.back();
  EXPECT_NEAR(end.y[scene.model.position_of(1).value], 2.0, 1e-8);
  const sim::RunSummary summary = sim::summarize(scene, run);
  ASSERT_TRUE(summary.free_bus);
  EXPECT_GT(summary.free_bus->final_attitude_change, 0.1);
  EXPECT_NEAR(end.energy.kinetic, 0, 1e-12);
  EXPECT_LT(balance, 1e-8);
}

TEST(JointDriver, TheSceneFileSaysWhatIsWrong) {
  const std::string rod = kRod;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = rod;
    text.replace(text.find(from), from.size(), to);
    return test::scene_error(text);
  };
  EXPECT_NE(with("profile: move", "profile: jog").find("drivers[0].profile: expected move or spin_up"),
            std::string::npos);
  EXPECT_NE(with("duration: 2", "duration: 0").find("drivers[0].duration"), std::string::npos);
  EXPECT_NE(with("joint: hinge, profile", "joint: elbow, profile").find("unknown joint 'elbow'"), std::string::npos);
  EXPECT_NE(with("run:", "latches: [{joint: hinge, position: 1, stiffness: 10, damping: 1}]\nrun:").find("has a latch"),
            std::string::npos);
  EXPECT_NE(with("run:", "initial: {dq: {hinge: 1}}\nrun:").find("initial.dq.hinge: joint 'hinge' is driven"),
            std::string::npos);
  EXPECT_NE(
      with("type: revolute, axis: [1, 0, 0]", "type: spherical").find("drivers[0].joint: joint 'hinge' is spherical"),
      std::string::npos);
  // The line and column of the field.
  EXPECT_NE(with("profile: move", "profile: jog").find("bad:12:29: drivers[0].profile"), std::string::npos);
}

TEST(JointDriver, AWrittenSceneReadsBackTheSame) {
  const sim::SceneFile file = sim::read_scene_text(kHubAndLink, "hub_and_link");
  const sim::Scene& scene = file.scene;
  const std::string text = sim::write_scene_text(file);
  const sim::Scene again = sim::load_scene_text(text, "again");
  const auto* d = again.elements_of<sim::JointDriver>().front();
  EXPECT_EQ(d->profile, sim::JointDriver::Profile::spin_up);
  EXPECT_EQ(d->amount, 4);
  EXPECT_EQ(d->duration, 3);
  EXPECT_TRUE(again.model.joints[d->joint].driven);
  const sim::RunResult first = sim::simulate(scene, scene.run), second = sim::simulate(again, again.run);
  EXPECT_EQ(first.trajectory.samples.back().y, second.trajectory.samples.back().y);
}

// J v at a time while the driver accelerates, against a central difference
// of the right-hand side at that time; a new time is a new base.
TEST(JointDriver, JacobianProductsAreTakenAtTheirTime) {
  const sim::Scene scene = sim::load_scene_text(kHubAndLink, "hub_and_link");
  sim::Dynamics dynamics(scene);
  std::vector<double> y = dynamics.initial_state();
  const std::size_t n = y.size();
  std::vector<double> v(n), Jv(n), plus(n), minus(n), y_plus(n), y_minus(n);
  for (std::size_t c = 0; c < n; ++c) y[c] += 0.1 * std::sin(1.0 + c), v[c] = std::cos(2.0 + 3.0 * c);
  for (const double t : {0.7, 2.1}) {
    ASSERT_TRUE(dynamics.jacobian_times(t, y.data(), v.data(), Jv.data()));
    const double h = 1e-6;
    for (std::size_t c = 0; c < n; ++c) y_plus[c] = y[c] + h * v[c], y_minus[c] = y[c] - h * v[c];
    dynamics.rhs(t, y_plus.data(), plus.data());
    dynamics.rhs(t, y_minus.data(), minus.data());
    for (std::size_t c = 0; c < n; ++c)
      EXPECT_NEAR(Jv[c], (plus[c] - minus[c]) / (2 * h), 1e-6 * (1 + std::abs(Jv[c]))) << t;
  }
}

TEST(JointDriver, ModesHoldTheDrivenJoints) {
  // The hub moved and held: the link alone rings on its spring,
  // omega^2 = k / (m2 b^2 + I2).
  const sim::Scene moved = sim::load_scene_text(
      kHubAndLink, "hub_and_link",
      {{"drivers.drive.profile", "move"}, {"drivers.drive.amount", "1"}, {"drivers.drive.duration", "1"}});
  const sim::RunResult run = sim::simulate(moved, moved.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::LinearizationState state = sim::state_of_run(moved, run.trajectory, moved.run.t_end);
  const sim::ModesResult modes = sim::linear_modes(moved, state.q, state.engaged, {});
  EXPECT_EQ(modes.coordinates, 1);
  ASSERT_EQ(modes.modes.size(), 1u);
  EXPECT_NEAR(modes.modes[0].frequency_hz, std::sqrt(k / (m2 * b * b + I2)) / (2 * M_PI), 1e-6);
  EXPECT_EQ(modes.modes[0].shape[0], 0);  // the hub stays
  // Spinning at the end: no state at rest to linearize about.
  const sim::Scene spinning = sim::load_scene_text(kHubAndLink, "hub_and_link");
  const sim::RunResult spun = sim::simulate(spinning, spinning.run);
  try {
    sim::state_of_run(spinning, spun.trajectory, spinning.run.t_end);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'drive' is still driven"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unfurl
