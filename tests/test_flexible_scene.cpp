// A flexible body from a scene file: the beam the file describes is the
// one beam_body makes, its modes through `unfurl modes` (linear_modes) are
// the cantilever's closed forms, and a child hangs on its tip and swings
// with its bending.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "unfurl/sim/elements/joint_driver.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

// The built-in spin-up beam: Simo and Vu-Quoc's section, eight cantilever
// modes (four in each bending plane), the hub held by its driver at t = 0.
TEST(FlexibleScene, TheFilesBeamHasTheCantileversFrequencies) {
  const sim::Scene scene = sim::load_builtin_scene("spinup_beam");
  const sim::ModesResult r = sim::linear_modes(scene, scene.q0, {}, {false});
  const double EI = 1.4e4, rho_A = 1.2, L = 10;
  const double beta_L[] = {1.87510407, 4.69409113, 7.85475744};
  std::vector<double> f;
  for (const sim::Mode& m : r.modes)
    if (m.kind == sim::ModeKind::elastic) f.push_back(m.frequency_hz);
  ASSERT_EQ(f.size(), 8u);
  for (int n = 0; n < 3; ++n) {
    const double exact = beta_L[n] * beta_L[n] * std::sqrt(EI / (rho_A * std::pow(L, 4))) / (2 * M_PI);
    // Equal stiffness in both planes: each frequency twice.
    EXPECT_NEAR(f[2 * n] / exact, 1.0, 5e-3) << "mode " << n + 1;
    EXPECT_NEAR(f[2 * n + 1] / exact, 1.0, 5e-3) << "mode " << n + 1;
  }
  // The scene's reduction is beam_body's.
  const auto& beam = *scene.model.bodies[1].flexible;
  const sim::flexible::FlexibleBody again = sim::flexible::beam_body(beam.beam);
  EXPECT_EQ(again.frequency_hz, beam.frequency_hz);
}

// `modes: {up_to: F}` keeps every fixed-interface mode up to F: a 1 m
// cantilever of EI 1000 N m^2 in both planes and 1 kg/m bends at 17.7,
// 110.9, 310.5 and 608.5 Hz in each plane (its twist at 707 Hz, its
// stretch at 2.5 kHz), so up to 400 Hz it keeps six, the same six as
// `modes: 6`; written back, the file says so again.
TEST(FlexibleScene, ModesUpToAFrequencyKeepsEveryOneBelowIt) {
  const auto cantilever = [](const std::string& modes) {
    return R"(
name: cantilever
base: {name: ground}
bodies:
  - name: beam
    parent: ground
    flexible:
      beam: {length: 1, axial_stiffness: 1.0e8, bending_stiffness: 1000, torsional_stiffness: 800,
             mass_per_length: 1, polar_inertia_per_length: 1.0e-4, elements: 8}
      modes: )" + modes + R"(
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
)";
  };
  const sim::SceneFile up_to = sim::read_scene_text(cantilever("{up_to: 400}"), "up to");
  const sim::SceneFile six = sim::read_scene_text(cantilever("6"), "six");
  const auto& f = *up_to.scene.model.bodies[0].flexible;
  ASSERT_EQ(f.modes(), 6);
  EXPECT_EQ(f.frequency_hz, six.scene.model.bodies[0].flexible->frequency_hz);
  EXPECT_LT(f.frequency_hz.maxCoeff(), 400);
  EXPECT_NEAR(f.frequency_hz.maxCoeff() / (7.85475744 * 7.85475744 * std::sqrt(1000.0) / (2 * M_PI)), 1.0, 5e-3);
  EXPECT_NE(sim::write_scene_text(up_to).find("modes: {up_to: 400}"), std::string::npos);
}

// A tip mass on a light flexible boom whose root a driver turns through a
// small angle and holds: the boom's first bending frequency with the tip
// mass is k / (m + 0.24 rho A L) with k = 3 EI / L^3 (Rayleigh); after the
// move the tip mass rings at it.
const std::string kTipMass = R"(
name: tip mass
base: {name: ground}
bodies:
  - name: hub
    parent: ground
    mass: 1
    inertia: [0.01, 0.01, 0.01]
    joint: {name: root, type: revolute, axis: [0, 0, 1], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: boom
    parent: hub
    flexible:
      beam: {length: 2, axial_stiffness: 1.0e8, bending_stiffness: 800, torsional_stiffness: 600,
             mass_per_length: 0.05, polar_inertia_per_length: 1.0e-5, elements: 8}
      modes: 2
      damping: 0
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: tip
    parent: boom
    mass: 2
    inertia: [1.0e-6, 1.0e-6, 1.0e-6]
    joint: {name: tip_mount, type: fixed, parent_point: [2, 0, 0], child_point: [0, 0, 0]}
drivers:
  - {joint: root, profile: move, amount: 0.05, duration: 0.2}
run: {t_end: 2, rtol: 1.0e-9, sample: 0.001}
)";

TEST(FlexibleScene, AChildOnTheTipRingsAtTheBoomsFrequency) {
  const sim::SceneFile file = sim::read_scene_text(kTipMass, "tip mass");
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const int c = sim::find_load_column(run.trajectory.load_columns, "deflection.boom");
  ASSERT_GE(c, 0);
  // The deflection's upward crossings of its mean after the move: twice
  // per period (|deflection| rectifies the ringing).
  std::vector<double> t, d;
  for (const sim::Sample& s : run.trajectory.samples)
    if (s.t > 0.3) t.push_back(s.t), d.push_back(s.loads.element[c]);
  double mean = 0;
  for (double x : d) mean += x / d.size();
  std::vector<double> crossings;
  for (std::size_t k = 1; k < d.size(); ++k)
    if (d[k - 1] < mean && d[k] >= mean)
      crossings.push_back(t[k - 1] + (mean - d[k - 1]) / (d[k] - d[k - 1]) * (t[k] - t[k - 1]));
  ASSERT_GE(crossings.size(), 6u);
  const double period = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double k = 3 * 800 / std::pow(2.0, 3), m = 2 + 0.24 * 0.05 * 2;
  EXPECT_NEAR(period / (2 * M_PI * std::sqrt(m / k)), 1.0, 2e-3);
  EXPECT_GT(mean, 0);
}

// A sensor at the boom's tip node reads what the tip body fixed there
// reads, and its acceleration is its position's second derivative (by
// central differences of 0.1 ms samples: the boom's stretch rings at
// 800 Hz). One on a rigid bracket beside the tip node reads what the tip
// body reads at the same point.
TEST(FlexibleScene, ASensorOnTheBoomMovesWithItsBending) {
  const sim::SceneFile file = sim::read_scene_text(
      kTipMass + "sensors:\n"
                 "  - {name: boom_tip, body: boom, point: [2, 0, 0], frame: inertial, measure: [position, acceleration]}\n"
                 "  - {name: mass, body: tip, point: [0, 0, 0], frame: inertial, measure: [position, acceleration]}\n"
                 "  - {name: bracket, body: boom, point: [2, 0.1, 0.05], frame: body, measure: [acceleration]}\n"
                 "  - {name: mass_side, body: tip, point: [0, 0.1, 0.05], frame: body, measure: [acceleration]}\n",
      "tip mass with sensors", {{"run.sample", "1.0e-4"}, {"run.t_end", "0.5"}});
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const std::vector<sim::Sample>& s = run.trajectory.samples;
  // Columns: boom_tip position x y z, acceleration x y z, then mass's.
  double largest = 0;
  for (const sim::Sample& x : s) largest = std::max(largest, std::abs(x.loads.sensor[4]));
  ASSERT_GT(largest, 1.0);  // the boom swings the mass by metres per second squared
  for (std::size_t k = 1; k + 1 < s.size(); ++k) {
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(s[k].loads.sensor[c], s[k].loads.sensor[6 + c], 1e-9 * largest);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s[k].loads.sensor[12 + c], s[k].loads.sensor[15 + c], 1e-9 * largest);
    const double dt = s[k + 1].t - s[k].t;
    for (int c = 0; c < 3; ++c) {
      const double difference =
          (s[k + 1].loads.sensor[c] - 2 * s[k].loads.sensor[c] + s[k - 1].loads.sensor[c]) / (dt * dt);
      EXPECT_NEAR(s[k].loads.sensor[3 + c], difference, 2e-3 * largest) << "t = " << s[k].t << ", axis " << c;
    }
  }
}


// A beam placed along the body's y from a root off the origin is the same
// beam as one along x from the origin, seen from another frame: equal
// frequencies, its (6 + m) mass matrix at any deformation the transformed
// one (so its mass points, point inertias and foreshortening all turned),
// its nodes' shapes turned, and a bracketed attachment's node on the axis.
TEST(FlexibleScene, ABeamAlongYIsTheBeamAlongXSeenTurned) {
  const sim::flexible::BeamSection section{1.2, 3.91e7, 2.64e6, 6692, 8967, 3.3333, 0.2252, 12};
  sim::flexible::BeamBodySpec along_x{
      section, 2, sim::flexible::ModalDamping::uniform(0.005), {Eigen::Vector3d(1.2, 0, 0.03)}};
  sim::flexible::BeamBodySpec along_y = along_x;
  along_y.axis = 1;
  along_y.root = Eigen::Vector3d(0, -0.6, 0.01);
  // The beam's own (x, y, z) are the body's (y, z, x).
  Eigen::Matrix3d R;
  R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  along_y.attachments = {along_y.root + R * along_x.attachments[0]};
  const sim::flexible::FlexibleBody x = sim::flexible::beam_body(along_x), y = sim::flexible::beam_body(along_y);
  ASSERT_EQ(x.modes(), 8);
  EXPECT_EQ(x.frequency_hz, y.frequency_hz);

  // The beam frame's velocity from the body frame's (v, w): R^T (v + w x root), R^T w.
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(6 + x.modes(), 6 + x.modes());
  Eigen::Matrix3d root_cross;
  root_cross << 0, -along_y.root.z(), along_y.root.y(), along_y.root.z(), 0, -along_y.root.x(), -along_y.root.y(),
      along_y.root.x(), 0;
  T.block<3, 3>(0, 0) = R.transpose();
  T.block<3, 3>(0, 3) = -R.transpose() * root_cross;
  T.block<3, 3>(3, 3) = R.transpose();
  const Eigen::VectorXd eta = Eigen::VectorXd::LinSpaced(x.modes(), -0.02, 0.03);
  const Eigen::MatrixXd expected = T.transpose() * x.inertia.mass_matrix(eta) * T;
  EXPECT_LT((y.inertia.mass_matrix(eta) - expected).norm(), 1e-12 * expected.norm());

  ASSERT_EQ(y.nodes.size(), 1u);
  EXPECT_LT((y.nodes[0].point - Eigen::Vector3d(0, 0.6, 0.01)).norm(), 1e-12);
  EXPECT_LT((y.nodes[0].shape.topRows<3>() - R * x.nodes[0].shape.topRows<3>()).norm(), 1e-12);
  EXPECT_LT((y.nodes[0].shape.bottomRows<3>() - R * x.nodes[0].shape.bottomRows<3>()).norm(), 1e-12);
  EXPECT_EQ(y.node_of(along_y.attachments[0]), 0);
  EXPECT_NEAR(y.station(y.mesh_nodes.back().point), 1.2, 1e-12);
}

// The built-in zfold_flexible against the rigid zfold, through its first
// two latch-ups (j1 at 2.85 s, j4 at 4.47 s): the deployment is slow
// against the panels' 17 Hz bending, so up to the second the two agree
// (the rigid panels given the flexible ones' Ixx, 0.4800: the beam leaves
// out the section's own inertia about its width). The latches catch at the
// same times; the outer panel's latch-up sets the panels ringing, by far
// more than the deployment bent them.
TEST(FlexibleScene, TheFlexibleZFoldDeploysAsTheRigidOneUntilItsLatchesCatch) {
  const sim::SceneFile flexible = sim::read_builtin_scene("zfold_flexible", {{"run.t_end", "5"}});
  std::vector<sim::Override> rigid_panels{{"run.t_end", "5"}};
  for (const char* panel : {"panel_A1", "panel_A2", "panel_A3"})
    rigid_panels.push_back({std::string("bodies.") + panel + ".inertia", "[0.48, 0.2702, 0.75]"});
  const sim::SceneFile rigid = sim::read_builtin_scene("zfold", rigid_panels);
  const sim::RunResult f = sim::simulate(flexible.scene, flexible.scene.run);
  const sim::RunResult r = sim::simulate(rigid.scene, rigid.scene.run);
  ASSERT_EQ(f.status, sim::RunStatus::finished) << sim::describe(f.failure);
  ASSERT_EQ(r.status, sim::RunStatus::finished) << sim::describe(r.failure);
  ASSERT_EQ(f.trajectory.events.size(), 2u);
  ASSERT_EQ(r.trajectory.events.size(), 2u);
  for (int e = 0; e < 2; ++e) {
    EXPECT_EQ(f.trajectory.events[e].joint, r.trajectory.events[e].joint);
    EXPECT_NEAR(f.trajectory.events[e].t, r.trajectory.events[e].t, 1e-4 * r.trajectory.events[e].t);
  }
  const double first = r.trajectory.events[0].t, second = r.trajectory.events[1].t;
  const int deflection = sim::find_load_column(f.trajectory.load_columns, "deflection.panel_A3");
  ASSERT_GE(deflection, 0);
  double deploying = 0, latched = 0;
  for (std::size_t k = 0; k < f.trajectory.samples.size() && k < r.trajectory.samples.size(); ++k) {
    const sim::Sample &a = f.trajectory.samples[k], &b = r.trajectory.samples[k];
    ASSERT_EQ(a.t, b.t);
    if (a.t < first) deploying = std::max(deploying, a.loads.element[deflection]);
    if (a.t > second) latched = std::max(latched, a.loads.element[deflection]);
    if (a.t >= second) continue;
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.y[j], b.y[j], 1e-4) << "t = " << a.t << ", joint " << j;
  }
  EXPECT_GT(latched, 10 * deploying);
}

// The driver on the flexible beam's own hinge (the sweep's driven extended
// joint) against the built-in spin-up, whose driver turns a hub the beam is
// clamped to: the same beam, the same motion. With RK4 at one step the two
// runs' elastic coordinates agree to round-off (measured: bit for bit), and
// the driver's torque differs by the hub's I theta'' alone.
TEST(FlexibleScene, ADriverOnTheBeamsOwnHingeTurnsItAsTheHubDoes) {
  const std::string direct = R"(
name: spinup direct
base: {name: ground}
bodies:
  - name: beam
    parent: ground
    flexible:
      beam: {length: 10, axial_stiffness: 2.8e7, bending_stiffness: [1.4e4, 1.4e4], torsional_stiffness: 1.0e4,
             mass_per_length: 1.2, polar_inertia_per_length: 1.0e-3, elements: 20}
      modes: 8
      damping: 0
    joint: {name: spin, type: revolute, axis: [0, 0, 1], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
drivers:
  - {joint: spin, profile: spin_up, amount: 6, duration: 15}
)";
  const std::vector<sim::Override> rk4 = {{"run.integrator", "rk4"}, {"run.dt", "0.001"}, {"run.t_end", "10"},
                                          {"run.sample", "0.01"}};
  const sim::Scene hub = sim::load_builtin_scene("spinup_beam", rk4);
  const sim::Scene own = sim::read_scene_text(direct, "spinup direct", rk4).scene;
  const sim::RunResult a = sim::simulate(hub, hub.run), b = sim::simulate(own, own.run);
  ASSERT_EQ(a.status, sim::RunStatus::finished) << sim::describe(a.failure);
  ASSERT_EQ(b.status, sim::RunStatus::finished) << sim::describe(b.failure);
  ASSERT_EQ(a.trajectory.samples.size(), b.trajectory.samples.size());
  const int eta = hub.model.first_elastic_position[1], m = hub.model.bodies[1].flexible->modes();
  ASSERT_EQ(own.model.first_elastic_position[0], eta);
  const int torque_a = sim::find_load_column(a.trajectory.load_columns, "drive_torque.spin");
  const int torque_b = sim::find_load_column(b.trajectory.load_columns, "drive_torque.spin");
  ASSERT_GE(torque_a, 0);
  ASSERT_GE(torque_b, 0);
  const sim::JointDriver& driver = *hub.elements_of<sim::JointDriver>().front();
  const double I_hub = hub.model.bodies[0].inertia_com(2, 2);
  double largest_eta = 0, largest_torque = 0;
  for (const sim::Sample& s : a.trajectory.samples) {
    for (int k = 0; k < m; ++k) largest_eta = std::max(largest_eta, std::abs(s.y[eta + k]));
    largest_torque = std::max(largest_torque, std::abs(s.loads.element[torque_a]));
  }
  for (std::size_t n = 0; n < a.trajectory.samples.size(); ++n) {
    const sim::Sample &sa = a.trajectory.samples[n], &sb = b.trajectory.samples[n];
    for (int k = 0; k < m; ++k) EXPECT_NEAR(sa.y[eta + k], sb.y[eta + k], 1e-12 * largest_eta) << "t = " << sa.t;
    const double hub_torque = I_hub * driver.at(sa.t).acceleration;
    EXPECT_NEAR(sa.loads.element[torque_a] - hub_torque, sb.loads.element[torque_b], 1e-10 * largest_torque)
        << "t = " << sa.t;
  }
}

}  // namespace
}  // namespace unfurl
