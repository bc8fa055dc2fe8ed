// Loops that close through flexible bodies: a crank-rocker four-bar whose
// coupler is a flexible beam, its loop split at a pin fixed to the beam's
// tip node, against the same four-bar with a rigid coupler (the limit of a
// stiff beam) and its own energy balance; the built-in pantograph_flexible
// (plates joined at their cross pivots' nodes) against the pantograph
// whose rigid panels bushings join.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {
namespace {

// Ground pivots 1 m apart along y, a 0.3 m crank and a 0.8 m rocker
// hinged about x, a 1 m coupler (1 kg) between their tips, swinging under
// gravity from a closed start (the crank at 0.6 rad). `coupler` is its
// body's mass or flexible block.
std::string four_bar(const std::string& coupler, const std::string& run) {
  return R"(name: four-bar
base: {name: ground}
gravity: [0, 0, -9.81]
bodies:
  - {name: crank, parent: ground, mass: 0.5, com: [0, 0, 0.15], inertia: [0.004, 0.004, 0.001],
     joint: {name: ja, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
  - {name: rocker, parent: ground, mass: 0.5, com: [0, 0, 0.4], inertia: [0.027, 0.027, 0.001],
     joint: {name: jb, type: revolute, axis: [1, 0, 0], parent_point: [0, 1, 0], child_point: [0, 0, 0]}}
  - name: coupler
    parent: crank
)" + coupler + R"(
    joint: {name: jc, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0.3], child_point: [0, 0, 0]}
  - {name: pin, parent: coupler, mass: 0.01, inertia: [1.0e-5, 1.0e-5, 1.0e-5],
     joint: {name: jp, type: fixed, parent_point: [0, 1, 0], child_point: [0, 0, 0]}}
  - {name: pin_image, parent: rocker, mass: 0.01, inertia: [1.0e-5, 1.0e-5, 1.0e-5],
     joint: {name: ji, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0.8], child_point: [0, 0, 0]}}
loops:
  - {name: closing, body: pin, image: pin_image}
initial:
  q: {ja: 0.6, jb: 0.38433288557615486, jc: -0.0832715967088914, ji: 0.13239551771495373}
)" + run;
}

std::string beam(double EI, double zeta, double EA) {
  std::ostringstream s;
  s << "    flexible:\n      beam: {length: 1, axis: y, axial_stiffness: " << EA << ", bending_stiffness: [" << EI << ", " << EI
    << "], torsional_stiffness: " << EI
    << ", mass_per_length: 1.0, polar_inertia_per_length: 1.0e-4, elements: 8}\n      modes: 3\n      damping: " << zeta;
  return s.str();
}

const char* kRigidCoupler =
    "    mass: 1.0\n    com: [0, 0.5, 0]\n    inertia: [0.08333333333333333, 1.0e-4, 0.08333333333333333]";
const char* kTightRun = "run: {t_end: 0.5, integrator: cvode-bdf, rtol: 1.0e-11, atol: 1.0e-13, sample: 0.01}\n";

RunResult run_of(const std::string& text) {
  const Scene scene = read_scene_text(text, "four-bar").scene;
  RunResult run = simulate(scene, scene.run);
  EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  return run;
}

double largest_angle_difference(const RunResult& a, const RunResult& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.trajectory.samples.size() && k < b.trajectory.samples.size(); ++k)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(a.trajectory.samples[k].y[c] - b.trajectory.samples[k].y[c]));
  return worst;
}

// The crank spins through half a turn in 0.5 s. As the coupler stiffens,
// the flexible four-bar's angles approach the rigid one's as its
// compliance, 1 / EI (measured: 9.7e-4, 9.7e-5, 1.1e-5 rad at EI = 1e3,
// 1e4, 1e5 N m^2); the rigid reference's regulator is held tight (v_max
// 1e5: its gap 3e-14 m) so that its own closure is not what differs.
TEST(FlexibleLoops, AStiffCouplerMovesAsTheRigidOne) {
  const RunResult rigid = run_of(four_bar(kRigidCoupler, std::string(kTightRun) + "regulator: {v_max: 1.0e5}\n"));
  const double soft = largest_angle_difference(run_of(four_bar(beam(1e4, 0.02, 1e8), kTightRun)), rigid);
  const double stiff = largest_angle_difference(run_of(four_bar(beam(1e5, 0.02, 1e8), kTightRun)), rigid);
  EXPECT_LT(soft, 2e-4);
  EXPECT_LT(stiff, 2e-5);
  EXPECT_GT(soft / stiff, 5) << "the difference is the coupler's compliance";
}

// Undamped, a soft coupler (EI = 50 N m^2, EA = 1e6 N) bends by
// centimetres while the crank spins: the energy stays, and the loop stays
// closed through the beam's tip node.
TEST(FlexibleLoops, TheEnergyStaysAndTheLoopStaysClosed) {
  const RunResult run =
      run_of(four_bar(beam(50, 0, 1e6), "run: {t_end: 2, integrator: cvode-bdf, rtol: 1.0e-9, atol: 1.0e-11, sample: 0.01}\n"));
  const int deflection = find_load_column(run.trajectory.load_columns, "deflection.coupler");
  ASSERT_GE(deflection, 0);
  double bent = 0, gap = 0;
  for (const Sample& s : run.trajectory.samples) {
    bent = std::max(bent, s.loads.element[deflection]);
    gap = std::max(gap, s.closure[0].distance);
  }
  EXPECT_GT(bent, 0.01) << "it bends";
  EXPECT_LT(gap, 1e-9);
  const double E0 = run.trajectory.samples.front().energy.balance();
  EXPECT_NEAR(run.trajectory.samples.back().energy.balance(), E0, 1e-7 * std::abs(E0));
}

// The built-in pantograph_flexible closes its three loops through its
// plates' nodes at compliant cross pivots; pantograph_compliant joins
// rigid panels by bushings of the same stiffness at the same points, with
// no loops at all. With its plates made a thousand times stiffer the
// flexible scene moves as the compliant one: within 1.1e-5 rad over the
// first 0.5 s (the 20 g pins apart), against 3.3e-3 rad with the plates as
// built.
TEST(FlexibleLoops, ThePantographWithStiffPlatesMovesAsTheCompliantOne) {
  std::vector<Override> stiff{{"run.t_end", "0.5"}};
  for (const char* panel : {"A1", "A2", "A3", "B1", "B2", "B3"})
    stiff.push_back({std::string("bodies.panel_") + panel + ".flexible.plate.bending_stiffness", "7.435e6"});
  const Scene flexible = load_builtin_scene("pantograph_flexible", stiff);
  const Scene compliant = load_builtin_scene("pantograph_compliant", {{"run.t_end", "0.5"}});
  const RunResult a = simulate(flexible, flexible.run), b = simulate(compliant, compliant.run);
  ASSERT_EQ(a.status, RunStatus::finished) << describe(a.failure);
  ASSERT_EQ(b.status, RunStatus::finished) << describe(b.failure);
  ASSERT_EQ(a.trajectory.samples.size(), b.trajectory.samples.size());
  double worst = 0, gap = 0;
  for (std::size_t k = 0; k < a.trajectory.samples.size(); ++k) {
    for (int j = 0; j < 8; ++j)
      worst = std::max(worst, std::abs(a.trajectory.samples[k].y[j] - b.trajectory.samples[k].y[j]));
    for (const ClosureError& e : a.trajectory.samples[k].closure) gap = std::max(gap, e.distance);
  }
  EXPECT_LT(worst, 2e-5);
  EXPECT_LT(gap, 1e-7);
}

}  // namespace
}  // namespace unfurl::sim
