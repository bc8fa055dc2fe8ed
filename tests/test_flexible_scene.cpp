// A flexible body from a scene file: the beam the file describes is the
// one beam_body makes, its modes through `unfurl modes` (linear_modes) are
// the cantilever's closed forms, and a child hangs on its tip and swings
// with its bending.
#include <gtest/gtest.h>

#include <cmath>

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
// 800 Hz).
TEST(FlexibleScene, ASensorOnTheBoomMovesWithItsBending) {
  const sim::SceneFile file = sim::read_scene_text(
      kTipMass + "sensors:\n"
                 "  - {name: boom_tip, body: boom, point: [2, 0, 0], frame: inertial, measure: [position, acceleration]}\n"
                 "  - {name: mass, body: tip, point: [0, 0, 0], frame: inertial, measure: [position, acceleration]}\n",
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
    const double dt = s[k + 1].t - s[k].t;
    for (int c = 0; c < 3; ++c) {
      const double difference =
          (s[k + 1].loads.sensor[c] - 2 * s[k].loads.sensor[c] + s[k - 1].loads.sensor[c]) / (dt * dt);
      EXPECT_NEAR(s[k].loads.sensor[3 + c], difference, 2e-3 * largest) << "t = " << s[k].t << ", axis " << c;
    }
  }
}

}  // namespace
}  // namespace unfurl
