// Natural frequencies against closed forms (a spring-restrained pendulum
// under gravity; a two-link chain's 2 x 2 eigenproblem), against an
// independent mass matrix (the deployed, latched z-fold with the tests'
// dense formulation), against the free decay of the nonlinear run (the
// z-fold ringing after latch-up; a four-bar, one loop, swinging about its
// equilibrium), with a free-floating bus (six rigid-body modes), and the
// pantographs: the compliant one's modes all elastic, the rigid one's
// loops flagged as near a branch point.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "dense_formulation.hpp"
#include "support.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

std::vector<const sim::Mode*> elastic_modes(const sim::ModesResult& r) {
  std::vector<const sim::Mode*> out;
  for (const sim::Mode& m : r.modes)
    if (m.kind == sim::ModeKind::elastic) out.push_back(&m);
  return out;
}

// A 2 kg bob, its centre 0.5 m below a hinge about x, inertia 0.03 about
// its centre, a torsion spring of 3 N m/rad and damping 0.2 N m s/rad,
// under gravity: omega^2 = (k + m g l) / (I + m l^2).
TEST(Modes, SpringRestrainedPendulumMatchesItsClosedForm) {
  const sim::Scene scene = sim::load_scene_text(R"(
name: pendulum
gravity: [0, 0, -9.81]
bodies:
  - name: bob
    parent: base
    mass: 2.0
    com: [0, 0, -0.5]
    inertia: [0.03, 0.03, 0.03]
    joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
springs:
  - {joint: h, stiffness: 3.0, free_position: 0, damping: 0.2}
initial: {q: {h: 0.3}}
)",
                                                  "pendulum");
  const sim::ModesResult r = sim::linear_modes(scene, scene.q0, {});
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_NEAR(r.q[0], 0.0, 1e-12);  // settled at the bottom
  const double I = 0.03 + 2.0 * 0.25, K = 3.0 + 2.0 * 9.81 * 0.5, omega = std::sqrt(K / I);
  EXPECT_NEAR(r.modes[0].frequency_hz, omega / (2 * M_PI), 1e-8 * omega);
  EXPECT_NEAR(r.modes[0].damping_ratio, 0.2 / (2 * std::sqrt(K * I)), 1e-8);
  EXPECT_EQ(r.modes[0].kind, sim::ModeKind::elastic);
  EXPECT_DOUBLE_EQ(r.modes[0].shape[0], 1.0);
}

TEST(Modes, TwoLinkChainMatchesItsTwoByTwoEigenproblem) {
  // Straight along y: link 1 (m1, centre a1 from its hinge, I1), link 2
  // hinged L1 along it (m2, a2, I2); torsion springs k1, k2; no gravity.
  const double m1 = 1.5, a1 = 0.4, I1 = 0.02, L1 = 0.9, m2 = 0.8, a2 = 0.3, I2 = 0.01, k1 = 5, k2 = 2;
  const sim::Scene scene = sim::load_scene_text(R"(
name: chain
bodies:
  - {name: one, parent: base, mass: 1.5, com: [0, 0.4, 0], inertia: [0.02, 0.01, 0.02],
     joint: {name: h1, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
  - {name: two, parent: one, mass: 0.8, com: [0, 0.3, 0], inertia: [0.01, 0.01, 0.01],
     joint: {name: h2, type: revolute, axis: [1, 0, 0], parent_point: [0, 0.9, 0], child_point: [0, 0, 0]}}
springs:
  - {joint: h1, stiffness: 5, free_position: 0}
  - {joint: h2, stiffness: 2, free_position: 0}
)",
                                                  "chain");
  const sim::ModesResult r = sim::linear_modes(scene, scene.q0, {});
  Eigen::Matrix2d M, K;
  M << I1 + m1 * a1 * a1 + I2 + m2 * (L1 + a2) * (L1 + a2), I2 + m2 * a2 * (a2 + L1),  //
      I2 + m2 * a2 * (a2 + L1), I2 + m2 * a2 * a2;
  K << k1, 0, 0, k2;
  // det(K - w^2 M) = 0: a quadratic in w^2.
  const double a = M.determinant(), b = -(K(0, 0) * M(1, 1) + K(1, 1) * M(0, 0)), c = K.determinant();
  const double w2_low = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a), w2_high = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
  ASSERT_EQ(r.modes.size(), 2u);
  EXPECT_NEAR(r.modes[0].frequency_hz, std::sqrt(w2_low) / (2 * M_PI), 1e-8);
  EXPECT_NEAR(r.modes[1].frequency_hz, std::sqrt(w2_high) / (2 * M_PI), 1e-8);
  // The shapes: (K - w^2 M) phi = 0.
  for (int k = 0; k < 2; ++k) {
    const double w2 = std::pow(2 * M_PI * r.modes[k].frequency_hz, 2);
    EXPECT_LT(((K - w2 * M) * r.modes[k].shape).norm(), 1e-6 * K.norm()) << k;
  }
}

TEST(Modes, LatchedZfoldMatchesAnIndependentMassMatrix) {
  const sim::Scene scene = sim::load_builtin_scene("zfold");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::LinearizationState state = sim::state_of_run(scene, run.trajectory, scene.run.t_end);
  const sim::ModesResult r = sim::linear_modes(scene, state.q, state.engaged);
  ASSERT_EQ(r.modes.size(), 4u);
  // Independently: M from the tests' dense formulation at the settled
  // state, K and C the springs' and latches' own (0.1 + 1000, 0.02 + 10).
  const test::Dense dense = test::dense_formulation(scene, Eigen::Map<const Eigen::VectorXd>(r.q.data(), 4));
  const Eigen::MatrixXd K = 1000.1 * Eigen::MatrixXd::Identity(4, 4), C = 10.02 * Eigen::MatrixXd::Identity(4, 4);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, dense.Mt);
  for (int k = 0; k < 4; ++k) {
    const double omega = std::sqrt(eig.eigenvalues()[k]);
    EXPECT_NEAR(r.modes[k].frequency_hz, omega / (2 * M_PI), 1e-7 * omega) << k;
    const Eigen::VectorXd phi = eig.eigenvectors().col(k);  // mass-normalized
    EXPECT_NEAR(r.modes[k].damping_ratio, phi.dot(C * phi) / (2 * omega), 1e-6) << k;
  }
}

// The times where x(t) - x_rest crosses zero upwards, by linear
// interpolation between samples from t0 on.
std::vector<double> upward_crossings(const sim::RunResult& run, int c, double x_rest, double t0) {
  std::vector<double> t;
  const auto& s = run.trajectory.samples;
  for (std::size_t k = 1; k < s.size(); ++k) {
    if (s[k - 1].t < t0) continue;
    const double a = s[k - 1].y[c] - x_rest, b = s[k].y[c] - x_rest;
    if (a < 0 && b >= 0) t.push_back(s[k - 1].t + (s[k].t - s[k - 1].t) * a / (a - b));
  }
  return t;
}

TEST(Modes, ZfoldsRingingAfterLatchUpHasItsFirstModesFrequency) {
  // After the latch-up the higher modes die away (damping ratios 0.1 to
  // 0.5) and the first (0.013) rings on: its damped period, measured on
  // the nonlinear run, is the linearization's.
  sim::Scene scene = sim::load_builtin_scene("zfold", {{"run.t_end", "40"}, {"run.sample", "0.002"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::LinearizationState state = sim::state_of_run(scene, run.trajectory, scene.run.t_end);
  const sim::ModesResult r = sim::linear_modes(scene, state.q, state.engaged);
  const std::vector<double> up = upward_crossings(run, 0, r.q[0], 15.0);
  ASSERT_GE(up.size(), 8u);
  const double measured = (up.size() - 1) / (up.back() - up.front());
  EXPECT_NEAR(measured, r.modes[0].damped_frequency_hz, 1e-3 * measured);
}

// The four-bar (one loop: 4 coordinates, 1 independent) from where a run
// with a damper at the crank comes to rest, and without the damper.
sim::ModesResult fourbar_at_rest(const sim::Scene& fourbar) {
  sim::Scene damped = sim::load_builtin_scene(
      "fourbar", {{"dampers", "[{joint: crank_pivot, damping: 0.3}]"}, {"run.t_end", "40"}, {"run.rtol", "1e-8"}});
  const sim::RunResult run = sim::simulate(damped, damped.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished);
  return sim::linear_modes(fourbar, sim::state_of_run(damped, run.trajectory, 40).q, {});
}

// The four-bar's run from q0 with rates 1e-4 x the mode's shape.
sim::RunResult nudged_fourbar(sim::Scene scene, const sim::ModesResult& r, double t_end) {
  scene.q0 = r.q;
  scene.p0.clear();
  for (int c = 0; c < scene.model.nv; ++c) scene.dq0[c] = 1e-4 * r.modes[0].shape[c];
  scene.run.t_end = t_end;
  scene.run.sample = 0.001;
  return sim::simulate(scene, scene.run);
}

TEST(Modes, FourBarSwingsAboutItsEquilibriumAtItsLinearizedFrequency) {
  // The regulated nonlinear run swings at the frequency of the
  // linearization in independent coordinates, the loop rigid.
  const sim::Scene fourbar = sim::load_builtin_scene("fourbar");
  const sim::ModesResult r = fourbar_at_rest(fourbar);
  ASSERT_EQ(r.loop_rank, 3);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.weak_loop_directions, 0);
  ASSERT_EQ(r.modes[0].kind, sim::ModeKind::elastic);
  const sim::RunResult run = nudged_fourbar(fourbar, r, 10);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const std::vector<double> up = upward_crossings(run, 0, r.q[0], 0.0);
  ASSERT_GE(up.size(), 8u);
  const double measured = (up.size() - 1) / (up.back() - up.front());
  EXPECT_NEAR(measured, r.modes[0].frequency_hz, 1e-4 * measured);
}

TEST(Modes, FourBarsUnstableEquilibriumGrowsAtItsLinearizedRate) {
  // Settled from its initial state the four-bar finds the equilibrium
  // where gravity's potential is highest: an unstable mode, whose growth
  // rate the nonlinear run shows: x(t) = v sinh(s t) / s.
  const sim::Scene fourbar = sim::load_builtin_scene("fourbar");
  const sim::ModesResult r = sim::linear_modes(fourbar, fourbar.q0, {});
  ASSERT_EQ(r.modes.size(), 1u);
  ASSERT_EQ(r.modes[0].kind, sim::ModeKind::unstable);
  const double s = -2 * M_PI * r.modes[0].frequency_hz;
  const sim::RunResult run = nudged_fourbar(fourbar, r, 1.0);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double predicted = 1e-4 * r.modes[0].shape[0] * std::sinh(s * 1.0) / s;
  EXPECT_NEAR(run.trajectory.samples.back().y[0] - r.q[0], predicted, 1e-2 * std::abs(predicted));
}

// The pendulum released at 2.5 rad is mid-swing when its run ends: Newton's
// full step from there climbed to the inverted equilibrium; the settle goes
// down to where it hangs, whose mode is the small swing's, omega^2 = m g d
// / (I + m d^2).
TEST(Modes, APendulumMidSwingSettlesWhereItHangs) {
  const sim::Scene pendulum = sim::load_builtin_scene("pendulum");
  const sim::RunResult run = sim::simulate(pendulum, pendulum.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::LinearizationState at = sim::state_of_run(pendulum, run.trajectory, pendulum.run.t_end);
  const sim::ModesResult r = sim::linear_modes(pendulum, at.q, at.engaged);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.modes[0].kind, sim::ModeKind::elastic);
  EXPECT_NEAR(std::remainder(r.q[0], 2 * M_PI), 0.0, 1e-9);
  const double f = std::sqrt(9.81 * 1.0 / (0.004 + 1.0)) / (2 * M_PI);
  EXPECT_NEAR(r.modes[0].frequency_hz, f, 1e-6 * f);
}

TEST(Modes, FreeFloatingBusHasSixRigidBodyModes) {
  const sim::Scene scene = sim::load_builtin_scene("zfold_free", {{"run.t_end", "12"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const sim::LinearizationState state = sim::state_of_run(scene, run.trajectory, scene.run.t_end);
  const sim::ModesResult r = sim::linear_modes(scene, state.q, state.engaged);
  ASSERT_EQ(r.modes.size(), 10u);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(r.modes[k].kind, sim::ModeKind::rigid_body) << k;
  const auto elastic = elastic_modes(r);
  ASSERT_EQ(elastic.size(), 4u);
  // Free-free: the wing's first mode stiffer than on a clamped bus.
  const sim::Scene clamped = sim::load_builtin_scene("zfold", {{"run.t_end", "12"}});
  const sim::RunResult clamped_run = sim::simulate(clamped, clamped.run);
  const sim::LinearizationState at = sim::state_of_run(clamped, clamped_run.trajectory, 12);
  EXPECT_GT(elastic[0]->frequency_hz, sim::linear_modes(clamped, at.q, at.engaged).modes[0].frequency_hz);
}

TEST(Modes, CompliantPantographIsElasticWhereTheRigidOnesLoopsAreWeak) {
  const sim::Scene compliant = sim::load_builtin_scene("pantograph_compliant");
  const sim::RunResult run = sim::simulate(compliant, compliant.run);
  const sim::LinearizationState state = sim::state_of_run(compliant, run.trajectory, compliant.run.t_end);
  const sim::ModesResult c = sim::linear_modes(compliant, state.q, state.engaged);
  ASSERT_EQ(c.modes.size(), 8u);
  EXPECT_EQ(elastic_modes(c).size(), 8u);
  // Its first mode is the z-fold's: both chains swing together and the pins
  // carry nothing.
  const sim::Scene zfold = sim::load_builtin_scene("zfold");
  const sim::RunResult zrun = sim::simulate(zfold, zfold.run);
  const sim::LinearizationState zstate = sim::state_of_run(zfold, zrun.trajectory, zfold.run.t_end);
  EXPECT_NEAR(c.modes[0].frequency_hz, sim::linear_modes(zfold, zstate.q, zstate.engaged).modes[0].frequency_hz,
              1e-4);
  // The rigid pantograph latched sits near its branch point: the loops
  // hold some directions only weakly, and it says so.
  const sim::Scene rigid = sim::load_builtin_scene("pantograph");
  const sim::RunResult rrun = sim::simulate(rigid, rigid.run);
  const sim::LinearizationState rstate = sim::state_of_run(rigid, rrun.trajectory, rigid.run.t_end);
  const sim::ModesResult r = sim::linear_modes(rigid, rstate.q, rstate.engaged);
  EXPECT_GT(r.weak_loop_directions, 0);
}

// Beyond 48 loop components (the generated arrays from 17 stages on) the
// rigid loop forces come from the sparse analysis, which a scene also gets
// by asking for the sparse closure solver: the same modes, where the loops
// have full rank (the four-bar at rest) and at the latched pantograph's
// branch point, where both analyses leave the weak directions out.
TEST(Modes, TheSparseAnalysisGivesTheDenseOnesModes) {
  const sim::Override sparse{"regulator.solver", "sparse"};
  const sim::ModesResult fourbar = fourbar_at_rest(sim::load_builtin_scene("fourbar"));
  const sim::ModesResult fourbar_sparse = fourbar_at_rest(sim::load_builtin_scene("fourbar", {sparse}));
  ASSERT_EQ(fourbar_sparse.modes.size(), 1u);
  EXPECT_NEAR(fourbar_sparse.modes[0].frequency_hz, fourbar.modes[0].frequency_hz, 1e-8 * fourbar.modes[0].frequency_hz);

  const sim::Scene rigid = sim::load_builtin_scene("pantograph");
  const sim::RunResult run = sim::simulate(rigid, rigid.run);
  const sim::LinearizationState state = sim::state_of_run(rigid, run.trajectory, rigid.run.t_end);
  const sim::ModesResult dense = sim::linear_modes(rigid, state.q, state.engaged);
  const sim::ModesResult by_sparse =
      sim::linear_modes(sim::load_builtin_scene("pantograph", {sparse}), state.q, state.engaged);
  ASSERT_EQ(by_sparse.modes.size(), dense.modes.size());
  for (std::size_t k = 0; k < dense.modes.size(); ++k) {
    EXPECT_NEAR(by_sparse.modes[k].frequency_hz, dense.modes[k].frequency_hz, 1e-6 * dense.modes[k].frequency_hz);
    EXPECT_NEAR(by_sparse.modes[k].damping_ratio, dense.modes[k].damping_ratio, 1e-6);
  }
}

}  // namespace
}  // namespace unfurl
