// A flexible body's mass points and floating-frame inertia invariants:
// the points hold the whole consistent mass matrix; M^(eta) from the
// invariants equals the sum over the points at any deformation; dT/d eta
// is the derivative of T; at rest the frame block is the plate's spatial
// inertia and the modal block the identity.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "unfurl/sim/flexible/inertia_invariants.hpp"
#include "unfurl/sim/flexible/mass_points.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"
#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim::flexible {
namespace {

PlateSpec panel() {
  PlateSpec s;
  s.length_x = 1.3, s.length_y = 0.7, s.bending_stiffness = 900, s.mass_per_area = 2.2;
  s.elements_x = 5, s.elements_y = 3;
  return s;
}

BeamSection yoke() {
  BeamSection s;
  s.length = 0.9, s.axial_stiffness = 3e7, s.bending_stiffness_y = 700, s.bending_stiffness_z = 1100;
  s.torsional_stiffness = 500, s.mass_per_length = 0.8, s.polar_inertia_per_length = 4e-4;
  s.elements = 6;
  return s;
}

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(MassPoints, HoldTheWholeConsistentMass) {
  const Structure plate = plate_structure(panel());
  EXPECT_LT(relative_difference(mass_matrix(plate_mass_points(panel()), plate.size()), plate.M), 1e-13);
  const Structure beam = beam_structure(yoke());
  EXPECT_LT(relative_difference(mass_matrix(beam_mass_points(yoke()), beam.size()), beam.M), 1e-13);
}

// The sum over the points of m_g B_g^T B_g, B_g = [E, -(r_g + Phi_g eta)~,
// Phi_g], and of the point inertias.
Eigen::MatrixXd direct_mass(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shape,
                            const Eigen::VectorXd& eta) {
  const int m = static_cast<int>(shape.cols());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(6 + m, 6 + m);
  for (const MassPoint& p : points) {
    Eigen::MatrixXd local(p.dofs.size(), m);
    for (size_t a = 0; a < p.dofs.size(); ++a) local.row(a) = shape.row(p.dofs[a]);
    const Eigen::Matrix3Xd Phi = p.N * local, Psi = p.R * local;
    Eigen::MatrixXd B(3, 6 + m), R = Eigen::MatrixXd::Zero(3, 6 + m);
    B << Mat3::Identity(), -skew(p.r + Phi * eta), Phi;
    R.middleCols<3>(3).setIdentity();
    R.rightCols(m) = Psi;
    M += p.m * B.transpose() * B + R.transpose() * p.J * R;
  }
  return M;
}

struct Case {
  std::vector<MassPoint> points;
  ModalBody body;
};

Case beam_case() {
  const Structure beam = beam_structure(yoke());
  return {beam_mass_points(yoke()), reduce(beam, {beam.dofs_of({0}), beam.dofs_of({yoke().elements}), 3, {}})};
}

// The points' exact positions with the foreshortening: the sum over them
// of m_g B_g^T B_g with rho_g = r_g + Phi_g eta - (1/2) (eta^T G_g eta) e_g,
// B_g = [E, -rho_g~, Phi_g - e_g eta^T G_g].
Eigen::MatrixXd direct_mass(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shape,
                            const std::vector<Shortening>& shortening, const Eigen::VectorXd& eta) {
  const int m = static_cast<int>(shape.cols());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(6 + m, 6 + m);
  for (size_t g = 0; g < points.size(); ++g) {
    const MassPoint& p = points[g];
    Eigen::MatrixXd local(p.dofs.size(), m);
    for (size_t a = 0; a < p.dofs.size(); ++a) local.row(a) = shape.row(p.dofs[a]);
    const Eigen::Matrix3Xd Phi = p.N * local, Psi = p.R * local;
    const Shortening& s = shortening[g];
    const Vec3 rho = p.r + Phi * eta - 0.5 * eta.dot(s.G * eta) * s.axis;
    Eigen::MatrixXd B(3, 6 + m), R = Eigen::MatrixXd::Zero(3, 6 + m);
    B << Mat3::Identity(), -skew(rho), Phi - s.axis * (s.G * eta).transpose();
    R.middleCols<3>(3).setIdentity();
    R.rightCols(m) = Psi;
    M += p.m * B.transpose() * B + R.transpose() * p.J * R;
  }
  return M;
}

TEST(InertiaInvariants, EqualTheSumOverThePointsAtAnyDeformation) {
  const Case c = beam_case();
  const InertiaInvariants invariants(c.points, c.body.shape);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd eta(invariants.coordinates());
    for (auto& e : eta) e = 0.05 * normal(random);
    const Eigen::MatrixXd direct = direct_mass(c.points, c.body.shape, eta);
    EXPECT_LT(relative_difference(invariants.mass_matrix(eta), direct), 1e-12);
  }
}

// With the foreshortening the invariants keep the kinetic energy to second
// order in the deformation: against the exact sum over the points, the
// frame block (S and J, to eta^2) differs at third order, the coupling (C
// to eta) at second, the modal block (constant) at first: halving the
// deformation divides the differences by about 8, 4 and 2.
TEST(InertiaInvariants, WithForeshorteningAgreeToTheirOrder) {
  const Case c = beam_case();
  const std::vector<Shortening> shortening = beam_shortening(yoke(), c.body.shape);
  const InertiaInvariants invariants(c.points, c.body.shape, shortening);
  const int m = invariants.coordinates();
  Eigen::VectorXd eta(m);
  // A unit modal coordinate moves this 0.7 kg beam by about a metre, and
  // its steepest modes far more: these are tenths of millimetres.
  eta << 3e-4, -2e-4, 5e-4, 1e-4, -4e-4, 2e-4, 3e-4, -1e-4, 2e-4;
  struct Errors {
    double frame, coupling, modal;
  };
  auto errors = [&](const Eigen::VectorXd& e) {
    const Eigen::MatrixXd d = invariants.mass_matrix(e) - direct_mass(c.points, c.body.shape, shortening, e);
    return Errors{d.topLeftCorner(6, 6).norm(), d.topRightCorner(6, m).norm(), d.bottomRightCorner(m, m).norm()};
  };
  for (int halving = 1; halving < 3; ++halving) {
    const Errors coarse = errors(eta / std::pow(2.0, halving - 1)), fine = errors(eta / std::pow(2.0, halving));
    EXPECT_NEAR(coarse.frame / fine.frame, 8.0, 1.0) << "halving " << halving;
    EXPECT_NEAR(coarse.coupling / fine.coupling, 4.0, 0.5) << "halving " << halving;
    EXPECT_NEAR(coarse.modal / fine.modal, 2.0, 0.25) << "halving " << halving;
  }
  // The foreshortening is there: a bent beam's points draw back, which
  // moves the frame block by far more than its truncation leaves.
  const Eigen::MatrixXd without = InertiaInvariants(c.points, c.body.shape).mass_matrix(eta);
  EXPECT_GT((invariants.mass_matrix(eta) - without).topLeftCorner(6, 6).norm(), 30 * errors(eta).frame);
}

TEST(InertiaInvariants, KineticGradientIsTheDerivativeOfT) {
  const Case c = beam_case();
  const InertiaInvariants invariants(c.points, c.body.shape, beam_shortening(yoke(), c.body.shape));
  const int m = invariants.coordinates();
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  Eigen::VectorXd eta(m), V(6 + m);
  for (auto& e : eta) e = 0.03 * normal(random);
  for (auto& x : V) x = normal(random);
  const Eigen::VectorXd g = invariants.kinetic_gradient(eta, V);
  const double h = 1e-6;
  for (int k = 0; k < m; ++k) {
    Eigen::VectorXd up = eta, down = eta;
    up[k] += h, down[k] -= h;
    const double dT = 0.5 * V.dot((invariants.mass_matrix(up) - invariants.mass_matrix(down)) * V) / (2 * h);
    EXPECT_NEAR(g[k], dT, 1e-7 * std::max(1.0, std::abs(dT))) << "coordinate " << k;
  }
}

// At rest: the frame block is the thin plate's spatial inertia about its
// corner, the modal block the identity (the modes are mass-normalized).
TEST(InertiaInvariants, AtRestThePlatesInertiaAndUnitModalMasses) {
  const PlateSpec s = panel();
  const Structure plate = plate_structure(s);
  auto node = [&](int i, int j) { return i + j * (s.elements_x + 1); };
  const ModalBody body = reduce(plate, {{plate.dof(node(0, 0), plate_w), plate.dof(node(0, 3), plate_w),
                                         plate.dof(node(0, 0), plate_w_x)},
                                        {},
                                        6,
                                        {}});
  const InertiaInvariants invariants(plate_mass_points(s), body.shape);
  const Eigen::MatrixXd M = invariants.mass_matrix(Eigen::VectorXd::Zero(6));
  const double m = s.mass_per_area * s.length_x * s.length_y, a = s.length_x, b = s.length_y;
  Mat3 J;
  J << m * b * b / 3, -m * a * b / 4, 0, -m * a * b / 4, m * a * a / 3, 0, 0, 0, m * (a * a + b * b) / 3;
  const Mat6 expected = spatial_inertia(m, Vec3(a / 2, b / 2, 0), J);
  EXPECT_LT(relative_difference(M.topLeftCorner(6, 6), expected), 1e-13);
  EXPECT_LT((M.bottomRightCorner(6, 6) - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-10);
  // The frame-elastic coupling is R^T M Phi, the reduction's.
  EXPECT_LT(relative_difference(M.topRightCorner(6, 6), body.coupling), 1e-10);
}

}  // namespace
}  // namespace unfurl::sim::flexible
