// Sensors against closed forms (a spinning body's centripetal acceleration
// in the body and inertial frames; a pendulum's tip acceleration at every
// sample, from its own angle and rate), their peaks independent of the
// output interval, and a scene's sensors written back as they were read.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl {
namespace {

double reading(const sim::Trajectory& tr, const sim::Sample& s, const std::string& column) {
  const int c = sim::find_load_column(tr.sensor_columns, column);
  if (c < 0) throw std::runtime_error("no sensor column " + column);
  return s.loads.sensor[c];
}

TEST(Sensors, SpinningBodyFeelsItsCentripetalAcceleration) {
  // A disc spinning freely at 3 rad/s about the base's z axis; sensors 0.5 m
  // out along its x axis, read in its frame and in the inertial one.
  const sim::Scene scene = sim::load_scene_text(R"(
name: spinner
bodies:
  - name: disc
    parent: base
    mass: 2.0
    inertia: [0.3, 0.3, 0.5]
    joint: {name: h, type: revolute, axis: [0, 0, 1], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: rim, body: disc, point: [0.5, 0, 0], measure: [acceleration, velocity, angular_rate, angular_acceleration]}
  - {name: rim_inertial, body: disc, point: [0.5, 0, 0], frame: inertial, measure: [position, acceleration]}
initial: {dq: {h: 3.0}}
run: {t_end: 2, sample: 0.05, rtol: 1.0e-10, atol: 1.0e-12}
)",
                                                  "spinner");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::Trajectory& tr = run.trajectory;
  for (const sim::Sample& s : tr.samples) {
    EXPECT_NEAR(reading(tr, s, "rim.acceleration.x"), -9 * 0.5, 1e-8) << s.t;
    EXPECT_NEAR(reading(tr, s, "rim.acceleration.y"), 0, 1e-8) << s.t;
    EXPECT_NEAR(reading(tr, s, "rim.velocity.y"), 3 * 0.5, 1e-8) << s.t;
    EXPECT_NEAR(reading(tr, s, "rim.angular_rate.z"), 3, 1e-8) << s.t;
    EXPECT_NEAR(reading(tr, s, "rim.angular_acceleration.z"), 0, 1e-8) << s.t;
    // Inertial: towards the axis from where the point is.
    const double x = reading(tr, s, "rim_inertial.position.x"), y = reading(tr, s, "rim_inertial.position.y");
    EXPECT_NEAR(std::hypot(x, y), 0.5, 1e-12);
    EXPECT_NEAR(reading(tr, s, "rim_inertial.acceleration.x"), -9 * x, 1e-7) << s.t;
    EXPECT_NEAR(reading(tr, s, "rim_inertial.acceleration.y"), -9 * y, 1e-7) << s.t;
  }
  const sim::RunSummary summary = sim::summarize(scene, run);
  bool found = false;
  for (const auto& p : summary.sensor_peaks)
    if (p.quantity == "peak_acceleration" && p.name == "rim") {
      found = true;
      EXPECT_NEAR(p.peak.value, 4.5, 1e-7);
    }
  EXPECT_TRUE(found);
}

// A compound pendulum: 1.5 kg, its centre 0.4 m below a hinge about x,
// 0.02 kg m^2 about the centre; a sensor at the tip, 0.7 m below the hinge.
// In the body frame the tip's acceleration is (0, L theta'', L theta'^2)
// with theta'' = -m g d sin(theta) / I_hinge.
TEST(Sensors, PendulumTipAccelerationMatchesItsClosedForm) {
  const sim::Scene scene = sim::load_scene_text(R"(
name: pendulum
gravity: [0, 0, -9.81]
bodies:
  - name: rod
    parent: base
    mass: 1.5
    com: [0, 0, -0.4]
    inertia: [0.02, 0.02, 0.005]
    joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: tip, body: rod, point: [0, 0, -0.7]}
initial: {q: {h: 1.2}}
run: {t_end: 4, sample: 0.01, rtol: 1.0e-10, atol: 1.0e-12}
)",
                                                  "pendulum");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double m = 1.5, d = 0.4, L = 0.7, I = 0.02 + m * d * d;
  double worst = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    const double theta = s.y[0], rate = s.q_dot[0], accel = -m * 9.81 * d * std::sin(theta) / I;
    worst = std::max({worst, std::abs(reading(run.trajectory, s, "tip.acceleration.y") - L * accel),
                      std::abs(reading(run.trajectory, s, "tip.acceleration.z") - L * rate * rate),
                      std::abs(reading(run.trajectory, s, "tip.acceleration.x"))});
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(Sensors, PeaksDoNotDependOnTheOutputInterval) {
  // The z-fold's outer panel tip through its latch-ups, sampled at 10 ms
  // and at 0.5 s: the peaks are over every step, the same.
  const std::vector<sim::Override> tip{{"sensors", "[{name: tip, body: panel_A3, point: [0, 0.6, 0]}]"},
                                       {"run.t_end", "10"}};
  std::vector<double> peak;
  for (const char* sample : {"0.01", "0.5"}) {
    std::vector<sim::Override> o = tip;
    o.push_back({"run.sample", sample});
    const sim::Scene scene = sim::load_builtin_scene("zfold", o);
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished);
    const sim::RunSummary s = sim::summarize(scene, run);
    ASSERT_EQ(s.sensor_peaks.size(), 1u);
    peak.push_back(s.sensor_peaks[0].peak.value);
  }
  EXPECT_GT(peak[0], 2 * sim::kStandardGravity);  // a latch-up shock of some g
  EXPECT_NEAR(peak[0], peak[1], 1e-9 * peak[0]);
}

TEST(Sensors, AreWrittenBackAsTheyWereRead) {
  const sim::SceneFile file = sim::read_scene_text(R"(
name: written
bodies:
  - {name: a, parent: base, mass: 1, inertia: [1, 1, 1],
     joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
sensors:
  - {name: s1, body: a, point: [0.1, 0.2, 0.3], frame: inertial, measure: [velocity, angular_acceleration]}
  - {name: s2, body: a}
)",
                                                   "written");
  const sim::Scene back = sim::read_scene_text(sim::write_scene_text(file), "back").scene;
  ASSERT_EQ(back.sensors.size(), 2u);
  EXPECT_EQ(back.sensors[0].point, sim::Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(back.sensors[0].frame, sim::SensorFrame::inertial);
  EXPECT_EQ(back.sensors[0].measures,
            (std::vector<sim::SensorQuantity>{sim::SensorQuantity::velocity, sim::SensorQuantity::angular_acceleration}));
  EXPECT_EQ(back.sensors[1].measures, std::vector<sim::SensorQuantity>{sim::SensorQuantity::acceleration});
  const std::string error = test::scene_error(R"(
name: bad
bodies:
  - {name: a, parent: base, mass: 1, inertia: [1, 1, 1],
     joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
sensors:
  - {name: s, body: a, measure: [jerk]}
)");
  EXPECT_NE(error.find("7:34: sensors[0].measure[0]: 'jerk'"), std::string::npos) << error;
}

}  // namespace
}  // namespace unfurl
