// Compliant hinges: a body on one has the modes of its pin's springs in
// closed form (radial and axial sqrt(k/m), tilt sqrt(k/I)) and sags by
// m g / k under gravity with the hinge's reaction carrying m g; energy is
// conserved, and balanced by the dissipated work when the pin damps; a
// stiff pin swings as a rigid hinge does; springs and latches act on the
// hinge's angle (the z-fold deploys and latches on compliant hinges, mixed
// with the compliant pantograph's bushings); written back as read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl {
namespace {

// A 2 kg body hung at its centre on a compliant hinge about x (its pin
// 1e5 N/m across, 2e5 N/m along, 1e3 N m/rad in tilt), a torsion spring
// of 3 N m/rad on the hinge, inertia (0.03, 0.05, 0.07).
std::string hung(const std::string& gravity, const std::string& damping) {
  return R"(
name: hung
gravity: )" + gravity + R"(
bodies:
  - name: bob
    parent: base
    mass: 2.0
    inertia: [0.03, 0.05, 0.07]
    joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0],
            compliance: {radial: 1.0e5, axial: 2.0e5, tilt: 1.0e3)" +
         damping + R"(}}
springs:
  - {joint: h, stiffness: 3.0, free_position: 0}
initial: {q: {h: 0.2}}
run: {t_end: 2, rtol: 1.0e-10, atol: 1.0e-12, sample: 0.01}
)";
}

TEST(CompliantJoints, APinsModesAndSagAreItsSpringsClosedForms) {
  const sim::Scene scene = sim::load_scene_text(hung("[0, 0, -9.81]", ""), "hung");
  ASSERT_EQ(scene.model.nv, 6);
  const sim::ModesResult r = sim::linear_modes(scene, scene.q0, {});
  ASSERT_EQ(r.modes.size(), 6u);
  // The hinge's turn against its spring (I_x), the tilts about y and z
  // (e1, e2 for an x axis), the pin across (twice) and along.
  std::vector<double> expected{std::sqrt(3 / 0.03), std::sqrt(1e3 / 0.05), std::sqrt(1e3 / 0.07),
                               std::sqrt(1e5 / 2), std::sqrt(1e5 / 2), std::sqrt(2e5 / 2)};
  std::sort(expected.begin(), expected.end());
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(2 * M_PI * r.modes[k].frequency_hz, expected[k], 1e-6 * expected[k]) << k;
  // Settled: the pin sagged m g / k down (along e2 = z for an x axis).
  const double sag = 2 * 9.81 / 1e5;
  EXPECT_NEAR(r.q[2], -sag, 1e-12);
  EXPECT_NEAR(r.q[1], 0, 1e-12);
  EXPECT_NEAR(r.q[0], 0, 1e-10);  // settled to 1e-11 rad
  // At rest there the hinge carries the weight: its reaction is m g.
  sim::Scene at_rest = scene;
  at_rest.q0 = r.q;
  at_rest.run.t_end = 0.01;
  const sim::RunResult run = sim::simulate(at_rest, at_rest.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  EXPECT_NEAR(run.trajectory.samples.front().loads.reaction[0].head<3>().norm(), 2 * 9.81, 1e-6);
}

TEST(CompliantJoints, EnergyIsConservedAndBalancedByTheDamping) {
  for (const bool damped : {false, true}) {
    sim::Scene scene = sim::load_scene_text(
        hung("[0, 0, -9.81]", damped ? ", radial_damping: 50, axial_damping: 80, tilt_damping: 0.5" : ""), "hung");
    // Off its axis and turning about all three: every coordinate moves.
    scene.dq0 = {2.0, 0.01, -0.02, 0.01, 0.3, -0.2};
    // The pin rings at 220 to 320 rad/s: tight enough that BDF's own
    // damping of it stays below what is measured.
    scene.run.rtol = 1e-12;
    scene.run.atol = 1e-14;
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished);
    const double E0 = run.trajectory.samples.front().energy.balance();
    double drift = 0;
    for (const sim::Sample& s : run.trajectory.samples) drift = std::max(drift, std::abs(s.energy.balance() - E0));
    const double dissipated = run.trajectory.samples.back().energy.dissipated;
    if (damped) {
      EXPECT_GT(dissipated, 1e-3);
    }
    EXPECT_LT(drift, 1e-7 * std::abs(E0)) << (damped ? "damped" : "undamped");
  }
}

TEST(CompliantJoints, AStiffPinSwingsAsARigidHinge) {
  const auto pendulum = [](const std::string& compliance) {
    return sim::load_scene_text(R"(
name: swing
gravity: [0, 0, -9.81]
bodies:
  - name: rod
    parent: base
    mass: 1.5
    com: [0, 0, -0.4]
    inertia: [0.02, 0.02, 0.005]
    joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0])" +
                                    compliance + R"(}
initial: {q: {h: 1.0}}
run: {t_end: 2, rtol: 1.0e-10, atol: 1.0e-12, sample: 0.01}
)",
                                "swing");
  };
  const sim::Scene rigid = pendulum(""), stiff = pendulum(
                                             ", compliance: {radial: 1.0e9, axial: 1.0e9, tilt: 1.0e7, "
                                             "radial_damping: 1.0e3, axial_damping: 1.0e3, tilt_damping: 10}");
  const sim::RunResult a = sim::simulate(rigid, rigid.run), b = sim::simulate(stiff, stiff.run);
  ASSERT_EQ(b.status, sim::RunStatus::finished);
  double worst = 0;
  for (std::size_t k = 0; k < a.trajectory.samples.size(); ++k)
    worst = std::max(worst, std::abs(a.trajectory.samples[k].y[0] - b.trajectory.samples[k].y[0]));
  EXPECT_LT(worst, 1e-5);
}

// Every hinge of the z-fold on a compliant pin, by --set.
std::vector<sim::Override> compliant_zfold_pins() {
  std::vector<sim::Override> o;
  for (const char* body : {"frame_A", "panel_A1", "panel_A2", "panel_A3"})
    o.push_back({std::string("bodies.") + body + ".joint.compliance",
                 "{radial: 1.0e6, axial: 1.0e6, tilt: 1.0e4, radial_damping: 100, axial_damping: 100, "
                 "tilt_damping: 3}"});
  return o;
}

TEST(CompliantJoints, SpringsAndLatchesActOnTheHingeAngle) {
  const sim::Scene rigid = sim::load_builtin_scene("zfold", {{"run.t_end", "17"}});
  std::vector<sim::Override> o = compliant_zfold_pins();
  o.push_back({"run.t_end", "17"});
  const sim::Scene compliant = sim::load_builtin_scene("zfold", o);
  ASSERT_EQ(compliant.model.nv, 24);
  const sim::RunResult a = sim::simulate(rigid, rigid.run), b = sim::simulate(compliant, compliant.run);
  ASSERT_EQ(b.status, sim::RunStatus::finished);
  const sim::RunSummary ra = sim::summarize(rigid, a), rb = sim::summarize(compliant, b);
  ASSERT_EQ(rb.latch_times.size(), 4u);
  for (std::size_t k = 0; k < ra.latch_times.size(); ++k) {
    EXPECT_EQ(ra.latch_times[k].first, rb.latch_times[k].first);
    EXPECT_NEAR(ra.latch_times[k].second, rb.latch_times[k].second, 5e-3) << ra.latch_times[k].first;
  }
  // The latches' torques and the hinges' moments as on rigid hinges (to 1 %:
  // measured 0.4 %). The hinge forces are not: the latch's damping torque
  // steps up as it engages and the pins ring (62 N rigid, 76 N here).
  for (std::size_t l = 0; l < ra.peak_latch_torque.size(); ++l)
    EXPECT_NEAR(ra.peak_latch_torque[l].peak.value, rb.peak_latch_torque[l].peak.value,
                0.01 * ra.peak_latch_torque[l].peak.value)
        << ra.peak_latch_torque[l].joint;
  for (std::size_t j = 0; j < ra.peak_hinge_moment.size(); ++j)
    EXPECT_NEAR(ra.peak_hinge_moment[j].peak.value, rb.peak_hinge_moment[j].peak.value,
                0.01 * ra.peak_hinge_moment[j].peak.value)
        << ra.peak_hinge_moment[j].joint;
}

TEST(CompliantJoints, MixWithBushingsAndAreWrittenBackAsRead) {
  // The compliant pantograph's cross-links are bushings; its root hinges
  // here are compliant pins too.
  std::vector<sim::Override> o{{"run.t_end", "10"}};
  for (const char* body : {"frame_A", "frame_B"})
    o.push_back({std::string("bodies.") + body + ".joint.compliance", "{radial: 1.0e6, axial: 1.0e6, tilt: 1.0e4}"});
  const sim::SceneFile file = sim::read_builtin_scene("pantograph_compliant", o);
  const sim::Scene back = sim::read_scene_text(sim::write_scene_text(file), "back").scene;
  EXPECT_EQ(back.elements_of<sim::JointCompliance>().size(), 2u);
  EXPECT_EQ(back.elements_of<sim::Bushing>().size(), 3u);
  EXPECT_EQ(sim::write_scene_text({back, file.visuals}), sim::write_scene_text(file));
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  EXPECT_EQ(sim::summarize(file.scene, run).latch_times.size(), 8u);
  EXPECT_NE(test::scene_error(R"(
name: bad
bodies:
  - {name: a, parent: base, mass: 1, inertia: [1, 1, 1],
     joint: {name: s, type: prismatic, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0],
             compliance: {radial: 1, axial: 1, tilt: 1}}}
)")
                .find("compliance is for revolute joints"),
            std::string::npos);
}

}  // namespace
}  // namespace unfurl
