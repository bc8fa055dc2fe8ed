// The lumped beam (`unfurl generate beam`, studies::generate_beam): rigid
// segments with bending springs against the Euler-Bernoulli cantilever's
// closed-form frequencies, converging at second order; and Simo and
// Vu-Quoc's spin-up, driven at the hub past the beam's first frequency:
// a chain of rigid bodies keeps the centrifugal stiffening, so its tip
// deflection stays bounded and converges as the segments shrink.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/inertia_invariants.hpp"
#include "unfurl/sim/flexible/mass_points.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

const studies::BeamSpec kSpec;

// The cantilever's n-th bending frequency, Hz: (beta_n L)^2 sqrt(EI / (rho A L^4)) / (2 pi).
double cantilever_frequency(int n) {
  const double beta_L[] = {1.87510407, 4.69409113, 7.85475744};
  return std::pow(beta_L[n], 2) *
         std::sqrt(kSpec.bending_stiffness / (kSpec.mass_per_length * std::pow(kSpec.length, 4))) / (2 * M_PI);
}

// The first three elastic frequencies of the beam at rest, the hub held.
std::vector<double> beam_frequencies(int segments) {
  const sim::Scene scene = studies::generate_beam(segments).scene;
  const sim::ModesResult r = sim::linear_modes(scene, scene.q0, {});
  std::vector<double> f;
  for (const sim::Mode& m : r.modes)
    if (m.kind == sim::ModeKind::elastic && f.size() < 3) f.push_back(m.frequency_hz);
  EXPECT_EQ(r.coordinates, segments);  // the hub is held by its driver
  return f;
}

TEST(LumpedBeam, CantileverFrequenciesConvergeToTheClosedForm) {
  const std::vector<double> coarse = beam_frequencies(20), fine = beam_frequencies(40);
  ASSERT_EQ(fine.size(), 3u);
  for (int n = 0; n < 3; ++n) {
    const double exact = cantilever_frequency(n);
    const double e_coarse = std::abs(coarse[n] / exact - 1), e_fine = std::abs(fine[n] / exact - 1);
    EXPECT_LT(e_fine, 0.005) << "mode " << n + 1;
    // Second order: halving the segments quarters the error.
    EXPECT_NEAR(e_coarse / e_fine, 4.0, 0.3) << "mode " << n + 1;
  }
}

// The tip's largest offset across the hub's turned axis over the run, and
// the largest after the spin-up.
struct TipDeflection {
  double largest = 0, after_spin_up = 0;
};

TipDeflection spin_up(int segments) {
  const sim::Scene scene = studies::generate_beam(segments).scene;
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished);
  const int x = sim::find_load_column(run.trajectory.sensor_columns, "tip.position.x");
  const int hub = scene.model.position_of(0).value;
  TipDeflection d;
  for (const sim::Sample& s : run.trajectory.samples) {
    const double theta = s.y[hub];
    const double across = -std::sin(theta) * s.loads.sensor[x] + std::cos(theta) * s.loads.sensor[x + 1];
    d.largest = std::max(d.largest, std::abs(across));
    if (s.t > kSpec.spin_up_time) d.after_spin_up = std::max(d.after_spin_up, std::abs(across));
  }
  return d;
}

TEST(LumpedBeam, TheSpunUpBeamStaysBoundedAndConverges) {
  // 6 rad/s is past the beam's first frequency (3.80 rad/s), where a
  // linear floating-frame model without stiffening diverges.
  ASSERT_GT(kSpec.spin_rate, 2 * M_PI * cantilever_frequency(0));
  const TipDeflection coarse = spin_up(3), medium = spin_up(6), fine = spin_up(12);
  // Below the quasi-static deflection of the non-rotating cantilever under
  // the peak spin-up load rho A x theta'', 11 q0 L^4 / (120 EI): the
  // centrifugal tension stiffens it.
  const double q0 = kSpec.mass_per_length * kSpec.length * 2 * kSpec.spin_rate / kSpec.spin_up_time;
  const double static_bound = 11 * q0 * std::pow(kSpec.length, 4) / (120 * kSpec.bending_stiffness);
  EXPECT_LT(fine.largest, static_bound);
  EXPECT_GT(fine.largest, 0.8 * static_bound);
  // Converging at second order in the segment length.
  EXPECT_NEAR((coarse.largest - medium.largest) / (medium.largest - fine.largest), 4.0, 0.6);
  // Spinning steadily afterwards, it rings by under a centimetre.
  EXPECT_LT(fine.after_spin_up, 0.01);
}

// The largest |tip . eta| over the 30 s run of y' = f(t, y), y = (eta,
// eta' or p) from rest, by RK4 at 1 ms; it stops past 1 km (diverged).
template <class F>
double largest_tip_deflection(const F& f, const Eigen::RowVectorXd& tip) {
  const int modes = static_cast<int>(tip.size());
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * modes);
  const double h = 1e-3;
  double largest = 0;
  for (int i = 0; i < 30000 && largest < 1e3; ++i) {
    const double t = i * h;
    const Eigen::VectorXd k1 = f(t, y), k2 = f(t + h / 2, y + h / 2 * k1), k3 = f(t + h / 2, y + h / 2 * k2),
                          k4 = f(t + h, y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    largest = std::max(largest, std::abs(tip.dot(y.head(modes))));
  }
  return largest;
}

// The same spin-up by the floating-frame (modal) model of a flexible body,
// integrated apart (RK4): the beam's in-plane bending as `modes`
// cantilever modes eta on the hub's turning frame, theta(t) prescribed.
// Lagrange's equations with T = (1/2) integral rho A [(theta' v)^2 +
// (v' + theta' x)^2] dx and V = (1/2) eta^T (K + theta'^2 K_G) eta:
//   eta'' + (K + theta'^2 (K_G - I)) eta = -theta'' c,
// c = integral rho A x phi dx (the frame's spin coupling), K_G the
// geometric stiffness of the centrifugal tension rho A (L^2 - x^2) / 2 per
// unit theta'^2. Without K_G the spin's softening -theta'^2 I outgrows the
// first mode's stiffness (3.80 rad/s)^2 once theta' passes it: the
// divergence of a plain linear floating frame (Kane, Ryan and Banerjee).
double modal_spin_up_largest_tip(int modes, bool stiffening) {
  sim::flexible::BeamSection s;
  s.length = kSpec.length;
  s.bending_stiffness_y = s.bending_stiffness_z = kSpec.bending_stiffness;
  s.mass_per_length = kSpec.mass_per_length;
  s.elements = 20;
  const sim::flexible::Structure beam = sim::flexible::beam_structure(s);
  // In-plane bending only: the hub's node and every other component held.
  std::vector<int> held = beam.dofs_of({0});
  for (int node = 1; node <= s.elements; ++node)
    for (int k : {0, 2, 3, 4}) held.push_back(beam.dof(node, k));
  const sim::flexible::ModalBody body = sim::flexible::reduce(beam, {held, {}, modes, {}});
  const Eigen::VectorXd c = body.coupling.row(5).transpose();
  const Eigen::MatrixXd K = (2 * M_PI * body.frequency_hz).array().square().matrix().asDiagonal();
  const Eigen::MatrixXd KG = body.shape.transpose() *
                             sim::flexible::geometric_stiffness(s, [&](double x) {
                               return kSpec.mass_per_length * (kSpec.length * kSpec.length - x * x) / 2;
                             }) *
                             body.shape;
  const Eigen::RowVectorXd tip = body.node_shape(beam, s.elements).row(1);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(modes, modes);
  const double W = kSpec.spin_rate, T = kSpec.spin_up_time;
  auto rate = [&](double t) { return t < T ? W / T * (t - T / (2 * M_PI) * std::sin(2 * M_PI * t / T)) : W; };
  auto acceleration = [&](double t) { return t < T ? W / T * (1 - std::cos(2 * M_PI * t / T)) : 0.0; };
  // y = (eta, eta').
  auto f = [&](double t, const Eigen::VectorXd& y) {
    const double w = rate(t);
    Eigen::VectorXd dy(2 * modes);
    dy.head(modes) = y.tail(modes);
    dy.tail(modes) = -(K + w * w * ((stiffening ? KG : 0 * KG) - I)) * y.head(modes) - acceleration(t) * c;
    return dy;
  };
  return largest_tip_deflection(f, tip);
}

TEST(LumpedBeam, TheModalBeamWithGeometricStiffnessFollowsIt) {
  // The lumped model's limit, by Richardson's extrapolation at second order.
  const double lumped = (4 * spin_up(12).largest - spin_up(6).largest) / 3;
  const double modal = modal_spin_up_largest_tip(4, true);
  EXPECT_NEAR(modal / lumped, 1.0, 3e-3) << modal << " m against " << lumped << " m";
  EXPECT_NEAR(modal_spin_up_largest_tip(2, true) / modal, 1.0, 3e-3);  // two modes suffice
  EXPECT_GT(modal_spin_up_largest_tip(4, false), 10 * lumped);         // without: it diverges
}

// The spin-up as the solver's flexible bodies will carry it: the floating
// frame's inertia invariants with the foreshortening in the points'
// kinematics (no geometric stiffness matrix), the frame turned at the
// driver's rate, Lagrange's equations for eta in Hamiltonian form:
//   p = [M^(eta) V]_eta,  p' = dT/d eta - K eta,  V = (0, 0, 0, 0, 0, theta', eta').
double invariant_spin_up_largest_tip(int modes, bool foreshortening) {
  sim::flexible::BeamSection s;
  s.length = kSpec.length;
  s.bending_stiffness_y = s.bending_stiffness_z = kSpec.bending_stiffness;
  s.mass_per_length = kSpec.mass_per_length;
  s.elements = 20;
  const sim::flexible::Structure beam = sim::flexible::beam_structure(s);
  std::vector<int> held = beam.dofs_of({0});
  for (int node = 1; node <= s.elements; ++node)
    for (int k : {0, 2, 3, 4}) held.push_back(beam.dof(node, k));
  const sim::flexible::ModalBody body = sim::flexible::reduce(beam, {held, {}, modes, {}});
  const sim::flexible::InertiaInvariants inertia(
      sim::flexible::beam_mass_points(s), body.shape,
      foreshortening ? sim::flexible::beam_shortening(s, body.shape) : std::vector<sim::flexible::Shortening>{});
  const Eigen::VectorXd K = (2 * M_PI * body.frequency_hz).array().square();
  const Eigen::RowVectorXd tip = body.node_shape(beam, s.elements).row(1);
  const double W = kSpec.spin_rate, T = kSpec.spin_up_time;
  auto rate = [&](double t) { return t < T ? W / T * (t - T / (2 * M_PI) * std::sin(2 * M_PI * t / T)) : W; };
  // y = (eta, p).
  auto f = [&](double t, const Eigen::VectorXd& y) {
    const Eigen::VectorXd eta = y.head(modes);
    const Eigen::MatrixXd M = inertia.mass_matrix(eta);
    Eigen::VectorXd V = Eigen::VectorXd::Zero(6 + modes);
    V[5] = rate(t);
    V.tail(modes) = M.bottomRightCorner(modes, modes).ldlt().solve(y.tail(modes) - M.bottomRows(modes).col(5) * V[5]);
    Eigen::VectorXd dy(2 * modes);
    dy.head(modes) = V.tail(modes);
    dy.tail(modes) = inertia.kinetic_gradient(eta, V) - K.cwiseProduct(eta);
    return dy;
  };
  return largest_tip_deflection(f, tip);
}

TEST(LumpedBeam, TheFloatingFrameWithForeshorteningFollowsIt) {
  const double lumped = (4 * spin_up(12).largest - spin_up(6).largest) / 3;
  const double invariant = invariant_spin_up_largest_tip(4, true);
  EXPECT_NEAR(invariant / lumped, 1.0, 3e-3) << invariant << " m against " << lumped << " m";
  // The same as the geometric stiffness's linear model above.
  EXPECT_NEAR(invariant / modal_spin_up_largest_tip(4, true), 1.0, 1e-4);
  EXPECT_GT(invariant_spin_up_largest_tip(4, false), 10 * lumped);  // without: it diverges
}

// The whole solver on the built-in scene: the beam read from the file,
// meshed, reduced (eight cantilever modes: four in the spin's plane),
// hung on the driven hub and run through simulate; its largest deflection
// from the loads (deflection.beam, every 0.01 s).
double scene_largest_deflection(bool stiffening) {
  sim::SceneFile file = sim::read_builtin_scene(
      "spinup_beam", {{"bodies.beam.flexible.geometric_stiffening", stiffening ? "true" : "false"}});
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const int c = sim::find_load_column(run.trajectory.load_columns, "deflection.beam");
  EXPECT_GE(c, 0);
  double largest = 0;
  for (const sim::Sample& s : run.trajectory.samples) largest = std::max(largest, s.loads.element[c]);
  return largest;
}

TEST(LumpedBeam, TheSpinUpSceneFollowsIt) {
  const double modal = modal_spin_up_largest_tip(4, true);
  const double scene = scene_largest_deflection(true);
  EXPECT_NEAR(scene / modal, 1.0, 1e-4) << scene << " m against " << modal << " m";
  EXPECT_GT(scene_largest_deflection(false), 10 * modal);  // the plain floating frame diverges
}

}  // namespace
}  // namespace unfurl
