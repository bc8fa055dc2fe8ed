// Joint limits (a range with a stop at each end that pushes and never
// pulls) against the closed form of a free disc bouncing between them, the
// energy balance with their work taken out, their scene errors and their
// file form; and the compliant pantograph's stowed snubbers, without which
// a 10-stage array hangs up folded.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/elements/joint_limit.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

constexpr double kInertia = 0.5, kStiffness = 200, kRate = 1.0, kEnd = 0.5;

// A disc turning freely at kRate from q = 0 between limits at -+kEnd.
std::string disc(const std::string& limit) {
  return R"(
name: disc
bodies:
  - name: disc
    parent: base
    mass: 1.0
    inertia: [0.5, 0.5, 0.5]
    joint: {name: hinge, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
limits:
  - )" + limit +
         R"(
initial: {q: {hinge: 0}, dq: {hinge: 1}}
run: {t_end: 2.5, sample: 0.0001, rtol: 1.0e-11, atol: 1.0e-12}
)";
}

sim::RunResult bounce(double damping) {
  const sim::Scene scene = sim::load_scene_text(
      disc("{joint: hinge, lower: -0.5, upper: 0.5, stiffness: 200, damping: " + std::to_string(damping) + "}"),
      "disc");
  return sim::simulate(scene, scene.run);
}

const sim::Sample& sample_at(const sim::RunResult& run, double t) {
  for (const sim::Sample& s : run.trajectory.samples)
    if (s.t >= t - 1e-9) return s;
  return run.trajectory.samples.back();
}

double limit_torque(const sim::RunResult& run, const sim::Sample& s) {
  return test::load_of(run.trajectory.load_columns, s.loads, "limit_torque.hinge");
}

// Undamped, the disc stays in contact half a period of the end's own
// oscillation (omega = sqrt(k / I)) and leaves as fast as it came:
// q(t) = kEnd + (kRate / omega) sin(omega (t - t_in)) while in contact.
TEST(JointLimit, AnUndampedEndReturnsTheDiscAsFastAsItCame) {
  const sim::RunResult run = bounce(0);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double omega = std::sqrt(kStiffness / kInertia), t_in = kEnd / kRate, t_out = t_in + M_PI / omega;
  int inside = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    if (s.t < t_in) {
      ++inside;
      EXPECT_EQ(limit_torque(run, s), 0.0) << s.t;  // nothing inside the range
    } else if (s.t < t_out) {
      const double x = (kRate / omega) * std::sin(omega * (s.t - t_in));
      EXPECT_NEAR(s.y[0], kEnd + x, 1e-8) << s.t;
      EXPECT_NEAR(limit_torque(run, s), -kStiffness * x, 1e-5) << s.t;
    }
  }
  EXPECT_GT(inside, 1000);
  // Between the ends, on its way back: q(t) = kEnd - kRate (t - t_out).
  const sim::Sample& back = sample_at(run, 1.0);
  EXPECT_NEAR(back.q_dot[0], -kRate, 1e-8);
  EXPECT_NEAR(back.y[0], kEnd - kRate * (back.t - t_out), 1e-8);
  // It reaches the lower end and is turned back there too.
  const sim::Sample& again = sample_at(run, t_out + 2 * kEnd / kRate + M_PI / omega + 0.1);
  EXPECT_NEAR(again.q_dot[0], kRate, 1e-7);
  // Its energy is the disc's: the end gives back all it stored (to the
  // run's accuracy at rtol 1e-11 across the stiffness's kink at contact:
  // 2.5e-10 of it measured).
  const double E0 = run.trajectory.samples.front().energy.total();
  for (const sim::Sample& s : run.trajectory.samples) ASSERT_NEAR(s.energy.total(), E0, 1e-8 * E0) << s.t;
  const sim::RunSummary summary = sim::summarize(sim::load_scene_text(disc("{joint: hinge, lower: -0.5, upper: "
                                                                           "0.5, stiffness: 200}"),
                                                                      "disc"),
                                                 run);
  ASSERT_EQ(summary.element_peaks.size(), 1u);
  EXPECT_EQ(summary.element_peaks[0].quantity, "peak_limit_torque");
  EXPECT_NEAR(summary.element_peaks[0].peak.value, kStiffness * kRate / omega, 1e-6 * kStiffness * kRate / omega);
}

// Damped, the end's torque -k x - c x' turns to pull before the disc is
// out; it then lets go (a stop never pulls) and the disc leaves at the
// rate x' it had when k x + c x' reached zero, the damped oscillation's
// x(t) = (v / omega_d) e^(-zeta omega t) sin(omega_d t).
TEST(JointLimit, ADampedEndLetsGoWhereItWouldPull) {
  const double c = 2, omega = std::sqrt(kStiffness / kInertia), zeta = c / (2 * std::sqrt(kStiffness * kInertia));
  const double omega_d = omega * std::sqrt(1 - zeta * zeta);
  const auto x = [&](double t) { return kRate / omega_d * std::exp(-zeta * omega * t) * std::sin(omega_d * t); };
  const auto x_dot = [&](double t) {
    return kRate * std::exp(-zeta * omega * t) *
           (std::cos(omega_d * t) - zeta * omega / omega_d * std::sin(omega_d * t));
  };
  double lo = 1e-6, hi = M_PI / omega_d;  // k x + c x' > 0 at lo, < 0 at hi
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (kStiffness * x(mid) + c * x_dot(mid) > 0 ? lo : hi) = mid;
  }
  const double exit_rate = x_dot(lo);
  ASSERT_LT(exit_rate, 0);
  ASSERT_GT(exit_rate, -kRate);

  const sim::RunResult run = bounce(c);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  EXPECT_NEAR(sample_at(run, 1.0).q_dot[0], exit_rate, 1e-7);
  // The energy it took is the disc's loss, and the balance holds with it
  // (less tightly than for smooth elements: the damping's bite at contact
  // is a jump that no event locates).
  const sim::Sample& end = run.trajectory.samples.back();
  const double E0 = run.trajectory.samples.front().energy.total();
  EXPECT_GT(end.energy.dissipated, 0.2 * E0);
  for (const sim::Sample& s : run.trajectory.samples) ASSERT_NEAR(s.energy.balance(), E0, 1e-6 * E0) << s.t;
}

TEST(JointLimit, AnOpenEndLetsTheJointGo) {
  const sim::Scene scene = sim::load_scene_text(disc("{joint: hinge, lower: -0.5, stiffness: 200}"), "disc");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::Sample& end = run.trajectory.samples.back();
  EXPECT_NEAR(end.y[0], kRate * end.t, 1e-9);
  EXPECT_EQ(limit_torque(run, end), 0.0);
}

TEST(JointLimit, SceneErrorsNameTheField) {
  const std::string neither = test::scene_error(disc("{joint: hinge, stiffness: 200}"));
  EXPECT_NE(neither.find("limits[0]: give lower, upper or both"), std::string::npos) << neither;
  const std::string crossed = test::scene_error(disc("{joint: hinge, lower: 0.5, upper: -0.5, stiffness: 200}"));
  EXPECT_NE(crossed.find("limits[0].upper: the upper end must lie above the lower"), std::string::npos) << crossed;
  const std::string soft = test::scene_error(disc("{joint: hinge, upper: 0.5, stiffness: 0}"));
  EXPECT_NE(soft.find("limits[0].stiffness"), std::string::npos) << soft;
}

TEST(JointLimit, WrittenBackAsRead) {
  const sim::SceneFile file = sim::read_scene_text(disc("{joint: hinge, upper: 0.5, stiffness: 200, damping: 2}"), "d");
  const sim::Scene again = sim::load_scene_text(sim::write_scene_text(file), "again");
  const std::vector<const sim::JointLimit*> limits = again.elements_of<sim::JointLimit>();
  ASSERT_EQ(limits.size(), 1u);
  EXPECT_TRUE(std::isinf(limits[0]->lower) && limits[0]->lower < 0);
  EXPECT_EQ(limits[0]->upper, 0.5);
  EXPECT_EQ(limits[0]->stiffness, 200);
  EXPECT_EQ(limits[0]->damping, 2);
}

// A compliant 10-stage array over its deployment (rtol 1e-7): every hinge
// latches with its stowed snubbers; without them the inner panels fold
// back through the stowed lazy-tongs' branch point and stay folded.
sim::RunSummary compliant_ten(studies::Snubbers snubbers) {
  const sim::SceneFile file =
      sim::apply_overrides(studies::generate_pantograph(10, studies::CrossPivots::compliant, snubbers),
                           {{"run.t_end", "8"}, {"run.rtol", "1e-7"}, {"run.atol", "1e-9"}, {"run.sample", "0.05"}});
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished);
  return sim::summarize(file.scene, run);
}

TEST(JointLimit, StowedSnubbersLetTheCompliantArrayDeploy) {
  const sim::RunSummary with = compliant_ten(studies::Snubbers::stowed);
  EXPECT_TRUE(with.unlatched.empty());
  ASSERT_EQ(with.latch_times.size(), 22u);
  for (const auto& [joint, t] : with.latch_times) {
    EXPECT_GT(t, 5.0) << joint;
    EXPECT_LT(t, 8.0) << joint;
  }
  const sim::RunSummary without = compliant_ten(studies::Snubbers::none);
  EXPECT_GE(without.unlatched.size(), 4u);
}

}  // namespace
}  // namespace unfurl
