// Flexible plates from a scene file (docs/FLEXIBLE.md): a cantilevered
// plate's frequencies against Leissa's, a hinge line tied rigid bending
// under a load as the closed form of cylindrical bending says, a plate
// pendulum's energy balance, and the plate z-fold deploying as the beam
// z-fold does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/flexible/plate_structure.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {
namespace {

// A square plate of side a clamped along its root edge (the fixed joint
// holds the frame), five normal modes kept: its frame-held modes are the
// cantilevered plate's. Leissa's 36-term Ritz values (J. Sound Vib.
// 31(3), 1973, nu = 0.3) are upper bounds: the 12 x 12 mesh lies within
// 8e-3 under them (as the mesh's own test, test_structural_modes.cpp).
TEST(FlexiblePlate, ACantileveredPlateHasLeissasFrequencies) {
  const double a = 0.8, D = 3100, rho_h = 2.7;
  const Scene scene = read_scene_text(R"(
name: cantilevered plate
base: {name: wall}
bodies:
  - name: plate
    parent: wall
    flexible:
      plate: {size: [0.8, 0.8], bending_stiffness: 3100, poisson: 0.3, mass_per_area: 2.7, elements: [12, 12]}
      modes: 5
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
)",
                                      "cantilevered plate")
                          .scene;
  const ModesResult r = linear_modes(scene, scene.q0, {}, {false});
  std::vector<double> lambda;
  for (const Mode& m : r.modes)
    if (m.kind == ModeKind::elastic) lambda.push_back(2 * M_PI * m.frequency_hz * a * a * std::sqrt(rho_h / D));
  const double leissa[] = {3.492, 8.525, 21.43, 27.33, 31.11};
  ASSERT_EQ(lambda.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_LT(lambda[k], leissa[k] * (1 + 5e-4)) << "mode " << k + 1;
    EXPECT_GT(lambda[k], leissa[k] * (1 - 8e-3)) << "mode " << k + 1;
  }
}

// A plate clamped along y = 0 (1 m wide, 1 m long, D = 1000 N m), its
// far edge a hinge line tied rigid, damped at 60 % so that it settles in
// its t_end; sensors at the tip line's ends and middle.
std::string tip_line_plate(double poisson, const std::string& extra) {
  return R"(
name: plate with a tip line
base: {name: wall}
bodies:
  - name: plate
    parent: wall
    flexible:
      plate: {size: [1, 1], bending_stiffness: 1000, poisson: )" +
         std::to_string(poisson) + R"(, mass_per_area: 2, elements: [4, 8], root_edge: y0, hinge_lines: [y1]}
      modes: 4
      damping: 0.6
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: left, body: plate, point: [0, 1, 0], frame: inertial, measure: [position]}
  - {name: middle, body: plate, point: [0.5, 1, 0], frame: inertial, measure: [position]}
  - {name: right, body: plate, point: [1, 1, 0], frame: inertial, measure: [position]}
run: {t_end: 1.5, rtol: 1.0e-10, sample: 0.01}
)" + extra;
}

// The settled z of the three tip sensors.
std::vector<double> settled_tip(double poisson, const std::string& extra) {
  const SceneFile file = read_scene_text(tip_line_plate(poisson, extra), "tip line");
  const RunResult run = simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  if (run.trajectory.empty()) return {NAN, NAN, NAN};
  const std::vector<double>& s = run.trajectory.samples.back().loads.sensor;
  return {s[2], s[5], s[8]};
}

// With nu = 0 a plate whose root is clamped and whose tip line is rigid
// bends in one direction only (w(y), its free edges free of moment), as a
// beam of EI = D b: w = F L^3 / (3 D b) under a force F at the line, the
// same at every point of it. The bicubic elements hold the cubic and the
// tie's constraint modes the static deformation, so the reduced model is
// exact for it (measured 4.7e-10 off, what the damped settling leaves).
TEST(FlexiblePlate, ARigidTipLineBendsAsTheClosedForm) {
  const double F = 10, L = 1, b = 1, D = 1000;
  const std::vector<double> z =
      settled_tip(0, "applied_forces:\n  - {body: plate, point: [0.5, 1, 0], force: [0, 0, -10], frame: base}\n");
  const double w = F * L * L * L / (3 * D * b);
  for (double zi : z) EXPECT_NEAR(-zi / w, 1.0, 1e-8);
  // Off the middle, the force twists the line as well; the middle still
  // moves by w.
  const std::vector<double> off =
      settled_tip(0, "applied_forces:\n  - {body: plate, point: [0.2, 1, 0], force: [0, 0, -10], frame: base}\n");
  EXPECT_NEAR(-off[1] / w, 1.0, 1e-8);
  EXPECT_GT(-off[0], -off[2] + 0.1 * w) << "the line tilts towards the load";
}

// The static deflection of a plate mesh solved directly (Eigen's LDLT on
// the full stiffness): the root nodes clamped, the tied nodes moving as one
// rigid line (w = r0 + r1 x + r2 y, its slopes r1, r2, no twist w_xy) that
// carries a force F along z at (x, y); the line's (r0, r1, r2).
Eigen::Vector3d pinned_tip_line(const flexible::PlateSpec& p, const std::vector<int>& root, const std::vector<int>& tied,
                                double x, double y, double F) {
  const flexible::Structure mesh = flexible::plate_structure(p);
  std::vector<int> role(mesh.size(), 0);  // 0 free, 1 held, 2 tied
  for (int n : root)
    for (int k = 0; k < 4; ++k) role[mesh.dof(n, k)] = 1;
  for (int n : tied)
    for (int k = 0; k < 4; ++k) role[mesh.dof(n, k)] = 2;
  std::vector<int> free;
  for (int d = 0; d < mesh.size(); ++d)
    if (role[d] == 0) free.push_back(d);
  // u = P [u_free; r].
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(mesh.size(), n + 3);
  for (int a = 0; a < n; ++a) P(free[a], a) = 1;
  for (int node : tied) {
    const Eigen::Vector3d at = mesh.nodes[node];
    P.row(mesh.dof(node, flexible::plate_w)).tail<3>() << 1, at.x(), at.y();
    P(mesh.dof(node, flexible::plate_w_x), n + 1) = 1;
    P(mesh.dof(node, flexible::plate_w_y), n + 2) = 1;
  }
  const Eigen::MatrixXd K = P.transpose() * mesh.K * P;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n + 3);
  f.tail<3>() << F, F * x, F * y;
  const Eigen::VectorXd u = K.ldlt().solve(f);
  return u.tail<3>();
}

// w at (x, y) on a tip line of pinned_tip_line.
double on_line(const Eigen::Vector3d& r, double x, double y) { return r[0] + r[1] * x + r[2] * y; }

// The same plate turned: its normal along the body's y (its own x along
// z, its y along x), held along x0 (the body's x axis) with x1 tied, the
// force along -y. The tip line moves by the same F L^3 / (3 D b) along -y
// (measured as above), so the placement, the x edges and the ties along
// the plate's y carry the same mechanics as the default orientation.
std::vector<double> turned_plate_tip(const std::string& brackets) {
  const SceneFile file = read_scene_text(R"(
name: turned plate
base: {name: wall}
bodies:
  - name: plate
    parent: wall
    flexible:
      plate: {size: [1, 1], normal: y, bending_stiffness: 1000, poisson: 0, mass_per_area: 2, elements: [8, 4],
              root_edge: x0, hinge_lines: [x1])" + brackets + R"(}
      modes: 4
      damping: 0.6
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: near, body: plate, point: [0, 0, 1], frame: inertial, measure: [position]}
  - {name: far, body: plate, point: [1, 0, 1], frame: inertial, measure: [position]}
applied_forces:
  - {body: plate, point: [0.5, 0, 1], force: [0, -10, 0], frame: base}
run: {t_end: 1.5, rtol: 1.0e-10, sample: 0.01}
)",
                                         "turned plate");
  const RunResult run = simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  return run.trajectory.empty() ? std::vector<double>(6, NAN) : run.trajectory.samples.back().loads.sensor;
}

TEST(FlexiblePlate, TurnedItBendsTheSame) {
  const std::vector<double> s = turned_plate_tip("");
  const double w = 10.0 / (3 * 1000);
  EXPECT_NEAR(-s[1] / w, 1.0, 1e-8);
  EXPECT_NEAR(-s[4] / w, 1.0, 1e-8);
  EXPECT_NEAR(s[0], 0, 1e-12);
  EXPECT_NEAR(s[3], 1, 1e-12);
}

// Brackets on edges along the plate's own y (x0 held, x1 tied): spanning
// the whole edge they are the whole edge; over [0, 0.25] and [0.75, 1] the
// tip line's ends move as the mesh solved directly with those nodes
// clamped and tied (the plate's x along the body's z, its y along x, w
// along y).
TEST(FlexiblePlate, TurnedBracketsFastenWhereTheyAre) {
  EXPECT_EQ(turned_plate_tip(", brackets: [[0, 1]]"), turned_plate_tip(""));
  const std::vector<double> s = turned_plate_tip(", brackets: [[0, 0.25], [0.75, 1]]");
  flexible::PlateSpec p;
  p.length_x = 1, p.length_y = 1, p.bending_stiffness = 1000, p.poisson = 0, p.mass_per_area = 2;
  p.elements_x = 8, p.elements_y = 4;
  const Eigen::Vector3d r = pinned_tip_line(p, {0, 9, 27, 36}, {8, 17, 35, 44}, 1, 0.5, -10);
  EXPECT_NEAR(s[1] / on_line(r, 1, 0), 1.0, 1e-8);
  EXPECT_NEAR(s[4] / on_line(r, 1, 1), 1.0, 1e-8);
  EXPECT_LT(s[1], 1.05 * turned_plate_tip("")[1]) << "further down (along -y) than with whole edges";
}

// With Poisson's ratio the section curls across the plate (anticlastic
// bending): the tip deflection lies between the plane-strain beam's F L^3
// / (3 D b), its curl fully held (EI = D b), and the plane-stress beam's F
// L^3 / (3 D (1 - nu^2) b), its curl free (EI = E t^3 b / 12).
TEST(FlexiblePlate, PoissonsRatioPutsItBetweenTheTwoBeams) {
  const double F = 10, L = 1, b = 1, D = 1000, nu = 0.3;
  const std::vector<double> z =
      settled_tip(nu, "applied_forces:\n  - {body: plate, point: [0.5, 1, 0], force: [0, 0, -10], frame: base}\n");
  const double held_curl = F * L * L * L / (3 * D * b);
  EXPECT_GT(-z[1], held_curl);
  EXPECT_LT(-z[1], held_curl / (1 - nu * nu));
}

// A force at a free node of the mesh (a corner of the tip edge, no tie):
// the node's four constraint modes hold the static deflection of the
// whole mesh exactly, so the settled corner moves as the mesh solved
// directly does (K u = f, the root edge clamped: Eigen's LDLT on the full
// stiffness), where the load bends and twists the plate (measured 1.5e-10
// off).
TEST(FlexiblePlate, AForceAtAMeshNodeBendsItAsTheWholeMesh) {
  const std::string scene = R"(
name: plate with a corner load
base: {name: wall}
bodies:
  - name: plate
    parent: wall
    flexible:
      plate: {size: [0.6, 1], bending_stiffness: 1000, poisson: 0.3, mass_per_area: 2, elements: [3, 5], root_edge: y0}
      modes: 4
      damping: 0.6
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: corner, body: plate, point: [0.6, 1, 0], frame: inertial, measure: [position]}
applied_forces:
  - {body: plate, point: [0.6, 1, 0], force: [0, 0, -10], frame: base}
run: {t_end: 1.5, rtol: 1.0e-10, sample: 0.01}
)";
  const SceneFile file = read_scene_text(scene, "corner load");
  const RunResult run = simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  const double w = -run.trajectory.samples.back().loads.sensor[2];

  flexible::PlateSpec p;
  p.length_x = 0.6, p.length_y = 1, p.bending_stiffness = 1000, p.poisson = 0.3, p.mass_per_area = 2;
  p.elements_x = 3, p.elements_y = 5;
  const flexible::Structure mesh = flexible::plate_structure(p);
  flexible::PlateEdges root;
  root.y0 = flexible::EdgeSupport::clamped;
  const std::vector<int> held = flexible::held_dofs(p, root);
  std::vector<int> free;
  for (int d = 0; d < mesh.size(); ++d)
    if (!std::binary_search(held.begin(), held.end(), d)) free.push_back(d);
  Eigen::MatrixXd K(free.size(), free.size());
  for (std::size_t a = 0; a < free.size(); ++a)
    for (std::size_t b = 0; b < free.size(); ++b) K(a, b) = mesh.K(free[a], free[b]);
  const int corner = mesh.dof(static_cast<int>(mesh.nodes.size()) - 1, flexible::plate_w);
  const std::size_t at = std::find(free.begin(), free.end(), corner) - free.begin();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(free.size());
  f[at] = -10;
  const double exact = -Eigen::VectorXd(K.ldlt().solve(f))[at];
  EXPECT_GT(exact, 0);
  EXPECT_NEAR(w / exact, 1.0, 1e-8);
}

// Brackets: a plate fastened to its root pin and to its tip pin only over
// [0, 0.25] and [0.75, 1] of its 1 m edges (four of the five nodes of
// each), a force at the tip pin's middle, between the brackets: the
// settled pin moves as the mesh solved directly with the same clamps and
// the same rigid tie (measured 7e-13 off: 3.917 mm), further than when the
// whole edges are fastened (3.424 mm); brackets spanning the whole edge
// are the whole edge; the brackets write back as read.
TEST(FlexiblePlate, BracketsFastenThePlateToItsPinsWhereTheyAre) {
  const std::string force = "applied_forces:\n  - {body: plate, point: [0.5, 1, 0], force: [0, 0, -10], frame: base}\n";
  const auto with_brackets = [&](const std::string& brackets) {
    std::string text = tip_line_plate(0.3, force);
    text.replace(text.find("hinge_lines: [y1]"), 17, "hinge_lines: [y1], brackets: " + brackets);
    const SceneFile file = read_scene_text(text, "brackets");
    const Scene again = read_scene_text(write_scene_text(file), "again").scene;
    EXPECT_EQ(again.model.bodies[0].flexible->plate->brackets, file.scene.model.bodies[0].flexible->plate->brackets);
    EXPECT_EQ(again.model.bodies[0].flexible->frequency_hz, file.scene.model.bodies[0].flexible->frequency_hz);
    const RunResult run = simulate(file.scene, file.scene.run);
    EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
    return run.trajectory.empty() ? NAN : -run.trajectory.samples.back().loads.sensor[5];
  };
  const double two = with_brackets("[[0, 0.25], [0.75, 1]]");
  flexible::PlateSpec p;
  p.length_x = 1, p.length_y = 1, p.bending_stiffness = 1000, p.poisson = 0.3, p.mass_per_area = 2;
  p.elements_x = 4, p.elements_y = 8;
  const std::vector<int> root = {0, 1, 3, 4}, tip = {40, 41, 43, 44};
  EXPECT_NEAR(two / -on_line(pinned_tip_line(p, root, tip, 0.5, 1, -10), 0.5, 1), 1.0, 1e-8);
  const double whole = -settled_tip(0.3, force)[1];
  EXPECT_GT(two, 1.05 * whole);
  EXPECT_EQ(with_brackets("[[0, 1]]"), whole);
}

// A plate pendulum released level: hinged along its root edge, it swings
// and bends under gravity; undamped, what gravity and the modes store
// with the swing's kinetic energy stays (RK4 at a step that resolves the
// tip line's constraint modes): measured within 2.8e-11 J of a swing of
// 10.9 J.
TEST(FlexiblePlate, APlatePendulumKeepsItsEnergy) {
  const SceneFile file = read_scene_text(R"(
name: plate pendulum
base: {name: ground}
gravity: [0, 0, -9.81]
bodies:
  - name: plate
    parent: ground
    flexible:
      plate: {size: [0.6, 1], corner: [-0.3, 0, 0], bending_stiffness: 40, poisson: 0.3, mass_per_area: 2,
              elements: [4, 6], hinge_lines: [y1]}
      modes: 4
      damping: 0
    joint: {name: pivot, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: tip
    parent: plate
    mass: 0.3
    inertia: [1.0e-3, 1.0e-3, 1.0e-3]
    joint: {name: tip_mount, type: fixed, parent_point: [0.1, 1, 0.02], child_point: [0, 0, 0]}
initial:
  q: {pivot: 0.3}
run: {t_end: 0.5, integrator: rk4, dt: 1.0e-4, sample: 0.01}
)",
                                         "plate pendulum");
  const RunResult run = simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  const int deflection = find_load_column(run.trajectory.load_columns, "deflection.plate");
  ASSERT_GE(deflection, 0);
  double swing = 0, bent = 0;
  for (const Sample& s : run.trajectory.samples) {
    swing = std::max(swing, s.energy.kinetic);
    bent = std::max(bent, s.loads.element[deflection]);
  }
  EXPECT_GT(swing, 1.0) << "it swings";
  EXPECT_GT(bent, 1e-3) << "it bends";
  EXPECT_NEAR(run.trajectory.samples.back().energy.balance(), run.trajectory.samples.front().energy.balance(),
              1e-9 * swing);
}

// Until its latches catch, the z-fold deploys as a mechanism: with plate
// panels as with beam panels its joint angles agree within 1e-4 rad and
// its first two latches catch at the same times (1e-4). The scene written
// back reads to the same plates.
TEST(FlexiblePlate, ThePlateZFoldDeploysAsTheBeamOne) {
  const SceneFile plates = read_builtin_scene("zfold_plates", {{"run.t_end", "5"}});
  const SceneFile beams = read_builtin_scene("zfold_flexible", {{"run.t_end", "5"}});
  const RunResult p = simulate(plates.scene, plates.scene.run);
  const RunResult b = simulate(beams.scene, beams.scene.run);
  ASSERT_EQ(p.status, RunStatus::finished) << describe(p.failure);
  ASSERT_EQ(b.status, RunStatus::finished) << describe(b.failure);
  ASSERT_EQ(p.trajectory.events.size(), 2u);
  ASSERT_EQ(b.trajectory.events.size(), 2u);
  for (int e = 0; e < 2; ++e) {
    EXPECT_EQ(p.trajectory.events[e].joint, b.trajectory.events[e].joint);
    EXPECT_NEAR(p.trajectory.events[e].t, b.trajectory.events[e].t, 1e-4 * b.trajectory.events[e].t);
  }
  const double second = b.trajectory.events[1].t;
  for (std::size_t k = 0; k < p.trajectory.samples.size() && k < b.trajectory.samples.size(); ++k) {
    const Sample &x = p.trajectory.samples[k], &y = b.trajectory.samples[k];
    ASSERT_EQ(x.t, y.t);
    if (x.t >= second) break;
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(x.y[j], y.y[j], 1e-4) << "t = " << x.t << ", joint " << j;
  }
  const Scene again = read_scene_text(write_scene_text(plates), "again").scene;
  for (int i = 0; i < again.model.size(); ++i) {
    const auto& f = plates.scene.model.bodies[i].flexible;
    if (!f) continue;
    ASSERT_TRUE(again.model.bodies[i].flexible && again.model.bodies[i].flexible->plate);
    EXPECT_EQ(again.model.bodies[i].flexible->frequency_hz, f->frequency_hz);
    EXPECT_EQ(again.model.bodies[i].flexible->plate->attachments, f->plate->attachments);
  }
}

}  // namespace
}  // namespace unfurl::sim
