// The Craig-Bampton reduction of flexible bodies: the reduced model on its
// floating frame (the frame's rigid inertia, the coupling R^T M Phi, unit
// modal masses, diagonal stiffness) reproduces the whole mesh's free-free
// frequencies exactly when every mode is kept and from above as modes are
// dropped; its frame-held modes are the cantilever's (closed form); the
// free-free beam against its closed form.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"
#include "unfurl/sim/flexible/plate_structure.hpp"
#include "unfurl/sim/flexible/structural_modes.hpp"

namespace unfurl::sim::flexible {
namespace {

BeamSection boom() {
  BeamSection s;
  s.length = 3.0;
  s.axial_stiffness = 5.0e7;
  s.bending_stiffness_y = 2.0e4;
  s.bending_stiffness_z = 4.5e4;
  s.torsional_stiffness = 1.2e4;
  s.mass_per_length = 1.4;
  s.polar_inertia_per_length = 3.0e-4;
  s.elements = 12;
  return s;
}

// The elastic frequencies of the reduced body left free: the (6 + m) pair
// [M_rr, C; C^T, I], diag(0, omega^2), with M_rr = R^T M R (a motion the
// structure does not model gets a unit inertia of its own: it decouples).
std::vector<double> free_frequencies(const Structure& s, const ModalBody& body) {
  const int m = body.coordinates();
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(6 + m, 6 + m), K = Eigen::MatrixXd::Zero(6 + m, 6 + m);
  M.topLeftCorner(6, 6) = s.rigid.transpose() * s.M * s.rigid;
  for (int r = 0; r < 6; ++r)
    if (M(r, r) == 0) M(r, r) = 1;
  M.topRightCorner(6, m) = body.coupling;
  M.bottomLeftCorner(m, 6) = body.coupling.transpose();
  for (int k = 0; k < m; ++k) K(6 + k, 6 + k) = std::pow(2 * M_PI * body.frequency_hz[k], 2);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  std::vector<double> f;
  for (int k = 6; k < 6 + m; ++k) f.push_back(std::sqrt(solver.eigenvalues()[k]) / (2 * M_PI));
  return f;
}

std::vector<double> mesh_free_frequencies(const Structure& s) {
  const StructuralModes modes = structural_modes(s, {});
  std::vector<double> f;
  for (int k = modes.rigid; k < modes.frequency_hz.size(); ++k) f.push_back(modes.frequency_hz[k]);
  return f;
}

std::vector<int> concat(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(ModalBody, EveryModeKeptReproducesTheFreeBeamExactly) {
  const Structure beam = beam_structure(boom());
  const int tip = boom().elements;
  ModalReduction reduction{beam.dofs_of({0}), beam.dofs_of({tip}), 0, {}};
  reduction.normal_modes = beam.size() - 12;
  const ModalBody body = reduce(beam, reduction);
  const std::vector<double> reduced = free_frequencies(beam, body), mesh = mesh_free_frequencies(beam);
  ASSERT_EQ(reduced.size(), mesh.size());
  for (size_t k = 0; k < 10; ++k) EXPECT_NEAR(reduced[k] / mesh[k], 1.0, 1e-9) << "mode " << k + 1;
}

// Free-free bending: (beta_n L)^2 sqrt(EI / (rho A L^4)), beta L = 4.7300,
// 7.8532; from four normal modes and the tip's six constraint modes.
TEST(ModalBody, AFewModesGiveTheFreeBeamFromAbove) {
  const BeamSection s = boom();
  const Structure beam = beam_structure(s);
  const ModalBody body = reduce(beam, {beam.dofs_of({0}), beam.dofs_of({s.elements}), 4, {}});
  EXPECT_EQ(body.coordinates(), 10);
  const std::vector<double> reduced = free_frequencies(beam, body), mesh = mesh_free_frequencies(beam);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_GE(reduced[k], mesh[k] * (1 - 1e-12)) << "mode " << k + 1;
    EXPECT_LT(reduced[k], mesh[k] * 1.01) << "mode " << k + 1;
  }
  for (double EI : {s.bending_stiffness_y, s.bending_stiffness_z})
    for (double bl : {4.73004074, 7.85320462}) {
      const double f = bl * bl * std::sqrt(EI / (s.mass_per_length * std::pow(s.length, 4))) / (2 * M_PI);
      double nearest = 1e300;
      for (double g : reduced) nearest = std::min(nearest, std::abs(g / f - 1));
      EXPECT_LT(nearest, 1e-2) << f << " Hz";
    }
}

// The orthonormal modes are the frame-held (cantilevered) structure's, as
// far as the basis reaches: the first bending frequency in each plane from
// four clamped-clamped modes and the tip's constraint modes, within 6e-5
// of the closed form (a Ritz value: from above).
TEST(ModalBody, FrameHeldModesAreTheCantilevers) {
  const BeamSection s = boom();
  const Structure beam = beam_structure(s);
  const ModalBody body = reduce(beam, {beam.dofs_of({0}), beam.dofs_of({s.elements}), 4, {}});
  const Eigen::MatrixXd gram = body.shape.transpose() * beam.M * body.shape;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(10, 10)).cwiseAbs().maxCoeff(), 1e-9);
  for (double EI : {s.bending_stiffness_y, s.bending_stiffness_z}) {
    const double f = 1.87510407 * 1.87510407 * std::sqrt(EI / (s.mass_per_length * std::pow(s.length, 4))) / (2 * M_PI);
    double nearest = 1e300;
    for (int k = 0; k < body.coordinates(); ++k) nearest = std::min(nearest, std::abs(body.frequency_hz[k] / f - 1));
    EXPECT_LT(nearest, 1e-4) << f << " Hz";
  }
  // The tip's shape: a unit coordinate moves the tip, the root not at all.
  EXPECT_EQ(body.node_shape(beam, 0).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(body.node_shape(beam, s.elements).cwiseAbs().maxCoeff(), 0.1);
}

// A panel: the frame held at two points of its inboard edge (w at both,
// w_x at one: the three rigid motions out of the plane, no more), both
// outboard brackets interface nodes; twelve normal modes.
TEST(ModalBody, APanelsFreeFrequenciesFromItsReducedModel) {
  PlateSpec spec;
  spec.length_x = 1.2, spec.length_y = 0.9;
  spec.bending_stiffness = 2.2e3, spec.mass_per_area = 1.9;
  spec.elements_x = 8, spec.elements_y = 6;
  const Structure plate = plate_structure(spec);
  auto node = [&](int i, int j) { return i + j * (spec.elements_x + 1); };
  const std::vector<int> frame = {plate.dof(node(0, 1), plate_w), plate.dof(node(0, 5), plate_w),
                                  plate.dof(node(0, 1), plate_w_x)};
  const std::vector<int> interface = concat(plate.dofs_of({node(8, 1)}), plate.dofs_of({node(8, 5)}));
  const ModalBody body = reduce(plate, {frame, interface, 12, {}});
  const std::vector<double> reduced = free_frequencies(plate, body), mesh = mesh_free_frequencies(plate);
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_GE(reduced[k], mesh[k] * (1 - 1e-12)) << "mode " << k + 1;
    EXPECT_LT(reduced[k], mesh[k] * 1.02) << "mode " << k + 1;
  }
  // R^T M R is the plate's own mass, first moments and inertias about the
  // frame's x and y axes.
  const Eigen::MatrixXd Mrr = plate.rigid.transpose() * plate.M * plate.rigid;
  const double m = spec.mass_per_area * spec.length_x * spec.length_y;
  EXPECT_NEAR(Mrr(2, 2), m, 1e-12 * m);
  EXPECT_NEAR(Mrr(2, 3), m * spec.length_y / 2, 1e-12 * m);   // v_z with w_x: the moment about x
  EXPECT_NEAR(Mrr(2, 4), -m * spec.length_x / 2, 1e-12 * m);  // with w_y
  EXPECT_NEAR(Mrr(3, 3), m * spec.length_y * spec.length_y / 3, 1e-12 * m);
  EXPECT_NEAR(Mrr(4, 4), m * spec.length_x * spec.length_x / 3, 1e-12 * m);
}

TEST(ModalBody, AFrameThatLeavesARigidMotionFreeIsRefused) {
  const Structure beam = beam_structure(boom());
  std::vector<int> frame = beam.dofs_of({0});
  frame.pop_back();  // the rotation about z left free
  EXPECT_THROW(reduce(beam, {frame, {}, 3, {}}), std::invalid_argument);
  EXPECT_THROW(reduce(beam, {beam.dofs_of({0}), {}, 1000, {}}), std::invalid_argument);
}

// A tie that shares a node with the frame's attachment, an interface node
// or another tie would be neither rigid nor held: refused.
TEST(ModalBody, OverlappingTiesAreRefused) {
  const Structure beam = beam_structure(boom());
  const int tip = boom().elements;
  EXPECT_THROW(reduce(beam, {beam.dofs_of({0}), {}, 2, {{0, 1}}}), std::invalid_argument);
  EXPECT_THROW(reduce(beam, {beam.dofs_of({0}), beam.dofs_of({tip}), 2, {{tip - 1, tip}}}), std::invalid_argument);
  EXPECT_THROW(reduce(beam, {beam.dofs_of({0}), {}, 2, {{tip - 2, tip - 1}, {tip - 1, tip}}}), std::invalid_argument);
  EXPECT_NO_THROW(reduce(beam, {beam.dofs_of({0}), {}, 2, {{tip - 1, tip}}}));
}

}  // namespace
}  // namespace unfurl::sim::flexible
