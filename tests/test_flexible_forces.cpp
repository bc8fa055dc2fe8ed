// Forces at the points of a flexible body (docs/FLEXIBLE.md): gravity on
// its deformed mass, and applied forces, point springs and bushings at its
// nodes. A clamped beam settles where Euler-Bernoulli's closed forms put
// it, and a flexible pendulum swinging and bending under gravity keeps its
// energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {
namespace {

// A 1 m beam clamped at the ground along x, EI = 1000 N m^2 about both
// axes, 1 kg/m, its tip a node (the sensor). Damped at 60 % so that it
// settles within its t_end: the first mode rings at 17.6 Hz.
const std::string kCantilever = R"(
name: cantilever
base: {name: ground}
bodies:
  - name: beam
    parent: ground
    flexible:
      beam: {length: 1, axial_stiffness: 1.0e8, bending_stiffness: 1000, torsional_stiffness: 800,
             mass_per_length: 1, polar_inertia_per_length: 1.0e-4, elements: 8}
      modes: 4
      damping: 0.6
    joint: {name: clamp, type: fixed, parent_point: [0, 0, 0], child_point: [0, 0, 0]}
sensors:
  - {name: tip, body: beam, point: [1, 0, 0], frame: inertial, measure: [position]}
run: {t_end: 0.6, rtol: 1.0e-10, sample: 0.01}
)";

constexpr double EI = 1000, rho_A = 1, L = 1;

// The beam's tip deflection at the end of a run of the cantilever with
// `extra` appended to its file: downwards, as its tip sensor sees it
// (deflection.beam is a length, whichever way the beam bends).
double settled_deflection(const std::string& extra) {
  const SceneFile file = read_scene_text(kCantilever + extra, "cantilever");
  const RunResult run = simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  const int c = find_load_column(run.trajectory.load_columns, "deflection.beam");
  EXPECT_GE(c, 0);
  if (c < 0 || run.trajectory.empty()) return NAN;
  const Sample& last = run.trajectory.samples.back();
  const double w = last.loads.element[c], tip_z = last.loads.sensor[2];
  EXPECT_NEAR(-tip_z, w, 1e-6 * w) << "the tip moves down by the deflection";
  return -tip_z;
}

// Its own weight: w(L) = rho A g L^4 / (8 EI), with four fixed-interface
// modes and the tip's constraint modes (measured 2e-12 off).
TEST(FlexibleForces, ItsWeightBendsACantileverAsTheClosedForm) {
  const double g = 9.81;
  const double w = settled_deflection("gravity: [0, 0, -9.81]\n");
  EXPECT_NEAR(w / (rho_A * g * std::pow(L, 4) / (8 * EI)), 1.0, 1e-8);
}

// A force at the tip: w = F L^3 / (3 EI), which the tip's constraint modes
// hold exactly (the cubic elements are exact for it); what is left is the
// second-order geometry the foreshortening adds, (w / L)^2 ~ 1e-5 at most
// (measured 6e-8).
TEST(FlexibleForces, ATipForceBendsItAsTheClosedForm) {
  const double F = 10;
  const double w = settled_deflection("applied_forces:\n  - {body: beam, point: [1, 0, 0], force: [0, 0, -10], frame: base}\n");
  EXPECT_NEAR(w / (F * std::pow(L, 3) / (3 * EI)), 1.0, 1e-5);
}

// A force at the tip in the body's frame follows the tip's node frame as it
// turns (by F L^2 / (2 EI) = 5e-3 rad here), a follower load: the
// transverse deflection is the same to that angle squared (measured
// 1.2e-5 smaller).
TEST(FlexibleForces, ABodyFrameForceFollowsTheTip) {
  const double F = 10;
  const double w = settled_deflection("applied_forces:\n  - {body: beam, point: [1, 0, 0], force: [0, 0, -10]}\n");
  const double fixed =
      settled_deflection("applied_forces:\n  - {body: beam, point: [1, 0, 0], force: [0, 0, -10], frame: base}\n");
  EXPECT_NEAR(w / (F * std::pow(L, 3) / (3 * EI)), 1.0, 1e-4);
  EXPECT_LT(w, fixed * (1 - 5e-6)) << "the force tilts with the tip and bends it less than a fixed one";
}

// A spring of k = 3 EI / L^3 under the tip takes half of a tip force:
// w = F / (k + 3 EI / L^3), as a point spring (measured 4e-7 off: its line
// tilts as the tip draws back) and as a bushing's z (2e-9).
TEST(FlexibleForces, ASpringUnderTheTipTakesItsShare) {
  const double F = 10, k = 3 * EI / std::pow(L, 3);
  const std::string force = "applied_forces:\n  - {body: beam, point: [1, 0, 0], force: [0, 0, -10], frame: base}\n";
  const double w_spring = settled_deflection(
      force + "point_springs:\n  - {body_a: ground, point_a: [1, 0, -1], body_b: beam, point_b: [1, 0, 0], "
              "stiffness: 3000, rest_length: 1}\n");
  EXPECT_NEAR(w_spring / (F / (k + 3 * EI / std::pow(L, 3))), 1.0, 1e-5);
  const double w_bushing = settled_deflection(
      force + "bushings:\n  - {name: prop, body_a: ground, point_a: [1, 0, 0], body_b: beam, point_b: [1, 0, 0], "
              "stiffness: [0, 0, 3000, 0, 0, 0]}\n");
  EXPECT_NEAR(w_bushing / (F / (k + 3 * EI / std::pow(L, 3))), 1.0, 1e-6);
}

// A flexible pendulum released level: it swings and bends under gravity,
// a damped spring at its tip pulls and dissipates (well below the load
// that would buckle the beam, beyond which the floating frame's
// second-order model has no bound). What gravity, the
// modes and the spring store, with what the spring dissipated, stays.
TEST(FlexibleForces, AFlexiblePendulumKeepsItsEnergyBalanceUnderGravity) {
  const std::string pendulum = R"(
name: flexible pendulum
base: {name: ground}
gravity: [0, 0, -9.81]
bodies:
  - name: beam
    parent: ground
    flexible:
      beam: {length: 1, axial_stiffness: 1.0e7, bending_stiffness: [200, 500], torsional_stiffness: 400,
             mass_per_length: 1, polar_inertia_per_length: 1.0e-4, elements: 8}
      modes: 4
      damping: 0
    joint: {name: pivot, type: revolute, axis: [0, 1, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
point_springs:
  - {body_a: ground, point_a: [0.5, 0.3, 0.2], body_b: beam, point_b: [1, 0, 0], stiffness: 40, rest_length: 0.5,
     damping: 0.5}
run: {t_end: 1, integrator: rk4, dt: 2.0e-5, sample: 0.01}
)";
  // RK4 at a step that resolves the tip's undamped constraint modes (800 Hz
  // axially): BDF damps them numerically (2.7e-6 J in 2 s at any rtol, its
  // steps set by their stability), which the balance would charge to the
  // forces.
  const SceneFile file = read_scene_text(pendulum, "flexible pendulum");
  const RunResult run = simulate(file.scene, file.scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  const EnergyParts& first = run.trajectory.samples.front().energy;
  const EnergyParts& last = run.trajectory.samples.back().energy;
  double swing = 0;
  for (const Sample& s : run.trajectory.samples) swing = std::max(swing, s.energy.kinetic);
  EXPECT_GT(swing, 0.1) << "it swings";
  EXPECT_GT(last.dissipated, 1e-3 * swing) << "the stay dissipates";
  EXPECT_NEAR(last.balance(), first.balance(), 1e-8 * swing);
}

}  // namespace
}  // namespace unfurl::sim
