// The plate and beam meshes of flexible bodies against closed forms and
// published values: a cantilevered beam's bending, stretch and twist
// frequencies; a plate's, simply supported (Navier's exact solution),
// clamped, cantilevered and free (Leissa, J. Sound Vib. 31(3), 1973,
// 36-term Ritz, nu = 0.3: upper bounds); and the convergence with the mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/plate_structure.hpp"
#include "unfurl/sim/flexible/structural_modes.hpp"

namespace unfurl::sim::flexible {
namespace {

using E = EdgeSupport;

// A square plate's frequency parameters lambda = omega a^2 sqrt(rho h / D),
// the first `count` elastic ones.
std::vector<double> square_plate_parameters(const PlateEdges& edges, int elements, int count) {
  PlateSpec spec;
  spec.length_x = spec.length_y = 0.8;
  spec.bending_stiffness = 3.1e3;
  spec.mass_per_area = 2.7;
  spec.elements_x = spec.elements_y = elements;
  const StructuralModes modes = structural_modes(plate_structure(spec), held_dofs(spec, edges));
  std::vector<double> lambda;
  for (int k = modes.rigid; k < modes.frequency_hz.size() && static_cast<int>(lambda.size()) < count; ++k)
    lambda.push_back(2 * M_PI * modes.frequency_hz[k] * spec.length_x * spec.length_x *
                     std::sqrt(spec.mass_per_area / spec.bending_stiffness));
  return lambda;
}

const PlateEdges kSimplySupported{E::simply_supported, E::simply_supported, E::simply_supported,
                                  E::simply_supported};
const PlateEdges kClamped{E::clamped, E::clamped, E::clamped, E::clamped};
const PlateEdges kCantilevered{E::clamped, E::free, E::free, E::free};
const PlateEdges kFree{};

// Navier: lambda = pi^2 (m^2 + n^2) for the simply supported square.
TEST(PlateModes, SimplySupportedSquareMatchesNaviersSolution) {
  const double exact[] = {2, 5, 5, 8, 10, 10};
  const std::vector<double> lambda = square_plate_parameters(kSimplySupported, 12, 6);
  ASSERT_EQ(lambda.size(), 6u);
  // The 12 x 12 mesh gives the (1, 3) and (3, 1) modes three elements a half-wave.
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(lambda[k] / (M_PI * M_PI * exact[k]), 1.0, 3e-4) << "mode " << k + 1;
}

// The conforming element converges from above at fourth order.
TEST(PlateModes, FrequenciesConvergeFromAboveAtFourthOrder) {
  const double exact = 2 * M_PI * M_PI;
  const double coarse = square_plate_parameters(kSimplySupported, 4, 1)[0] - exact;
  const double fine = square_plate_parameters(kSimplySupported, 8, 1)[0] - exact;
  EXPECT_GT(fine, 0);
  EXPECT_NEAR(coarse / fine, 16.0, 2.0);
}

// Leissa's Ritz values are upper bounds to the exact ones: the fine mesh
// lies within `below` under them and never above by more than round-off.
void expect_near_leissa(const std::vector<double>& lambda, const std::vector<double>& leissa, double below) {
  ASSERT_GE(lambda.size(), leissa.size());
  for (size_t k = 0; k < leissa.size(); ++k) {
    EXPECT_LT(lambda[k], leissa[k] * (1 + 5e-4)) << "mode " << k + 1;
    EXPECT_GT(lambda[k], leissa[k] * (1 - below)) << "mode " << k + 1;
  }
}

TEST(PlateModes, ClampedSquareMatchesLeissa) {
  expect_near_leissa(square_plate_parameters(kClamped, 12, 6), {35.99, 73.39, 73.39, 108.2, 131.6, 132.2}, 3e-3);
}

TEST(PlateModes, CantileveredSquareMatchesLeissa) {
  expect_near_leissa(square_plate_parameters(kCantilevered, 12, 5), {3.492, 8.525, 21.43, 27.33, 31.11}, 8e-3);
}

// Free, with its three rigid motions (a translation and two tilts) found
// and set apart.
TEST(PlateModes, FreeSquareMatchesLeissa) {
  expect_near_leissa(square_plate_parameters(kFree, 12, 5), {13.49, 19.79, 24.43, 35.02, 35.02}, 1.2e-2);
  PlateSpec spec;
  spec.elements_x = spec.elements_y = 4;
  EXPECT_EQ(structural_modes(plate_structure(spec), {}).rigid, 3);
}

// The shapes are mass-normalized and zero where held.
TEST(PlateModes, ShapesAreMassNormalizedAndHeld) {
  PlateSpec spec;
  spec.mass_per_area = 7.5;
  spec.elements_x = 4, spec.elements_y = 3;
  const Structure plate = plate_structure(spec);
  const std::vector<int> held = held_dofs(spec, kCantilevered);
  const StructuralModes modes = structural_modes(plate, held);
  const Eigen::MatrixXd gram = modes.shape.transpose() * plate.M * modes.shape;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff(), 1e-10);
  for (int d : held) EXPECT_EQ(modes.shape.row(d).cwiseAbs().maxCoeff(), 0.0);
  // A plate's total mass: a rigid translation w = 1 has kinetic energy m / 2.
  Eigen::VectorXd lift = Eigen::VectorXd::Zero(plate.size());
  for (int node = 0; node < static_cast<int>(plate.nodes.size()); ++node) lift[plate.dof(node, plate_w)] = 1;
  EXPECT_NEAR(lift.dot(plate.M * lift), spec.mass_per_area * spec.length_x * spec.length_y, 1e-12);
}

// A cantilevered beam: bending in each plane with its own EI, against
// (beta_n L)^2 sqrt(EI / (rho A L^4)); stretch and twist against
// (2n - 1) pi / (2 L) sqrt(EA / rho A) and sqrt(GJ / rho I_p).
TEST(BeamModes, CantileverMatchesTheClosedForms) {
  BeamSection s;
  s.length = 2.5;
  s.axial_stiffness = 7.0e7;
  s.bending_stiffness_y = 1.1e4;
  s.bending_stiffness_z = 3.3e4;
  s.torsional_stiffness = 8.0e3;
  s.mass_per_length = 0.9;
  s.polar_inertia_per_length = 2.0e-4;
  s.elements = 16;
  const StructuralModes modes = structural_modes(beam_structure(s), {0, 1, 2, 3, 4, 5});
  ASSERT_EQ(modes.rigid, 0);
  // Each expected frequency is among the computed ones, to `tolerance`.
  auto expect_among = [&](double f, double tolerance) {
    double nearest = 1e300;
    for (int k = 0; k < modes.frequency_hz.size(); ++k)
      nearest = std::min(nearest, std::abs(modes.frequency_hz[k] / f - 1));
    EXPECT_LT(nearest, tolerance) << f << " Hz";
  };
  const double beta_L[] = {1.87510407, 4.69409113, 7.85475744};
  for (double EI : {s.bending_stiffness_y, s.bending_stiffness_z})
    for (double bl : beta_L)
      expect_among(bl * bl * std::sqrt(EI / (s.mass_per_length * std::pow(s.length, 4))) / (2 * M_PI), 1e-4);
  // Stretch and twist are linear elements: second order, (k h)^2 / 24 for
  // the wave number k, 4e-4 and 3.6e-3 for the first two modes.
  for (int n = 1; n <= 2; ++n) {
    const double wave = (2 * n - 1) * M_PI / (2 * s.length) / (2 * M_PI);
    const double tolerance = std::pow(2 * M_PI * wave * s.length / s.elements, 2) / 24 * 1.1;
    expect_among(wave * std::sqrt(s.axial_stiffness / s.mass_per_length), tolerance);
    expect_among(wave * std::sqrt(s.torsional_stiffness / s.polar_inertia_per_length), tolerance);
  }
}

// A honeycomb panel as a beam: its first bending omega^2 lies 4e-10 below
// its in-plane bending's highest mesh mode at 12 elements, 4e-14 at 120
// (it falls as the elements^4), and the cantilever still has no rigid
// motion; its first bending mode is the closed form's.
TEST(BeamModes, AStiffContrastIsNotARigidMotion) {
  for (int elements : {12, 120}) {
    BeamSection s;
    s.length = 1.2;
    s.axial_stiffness = 3.91e7;
    s.bending_stiffness_y = 2.64e6;
    s.bending_stiffness_z = 6692;
    s.torsional_stiffness = 8967;
    s.mass_per_length = 10.0 / 3;
    s.polar_inertia_per_length = 0.2252;
    s.elements = elements;
    const StructuralModes modes = structural_modes(beam_structure(s), {0, 1, 2, 3, 4, 5});
    ASSERT_EQ(modes.rigid, 0) << elements << " elements";
    const double first = 1.87510407 * 1.87510407 *
                         std::sqrt(s.bending_stiffness_z / (s.mass_per_length * std::pow(s.length, 4))) / (2 * M_PI);
    EXPECT_NEAR(modes.frequency_hz[0] / first, 1.0, 1e-4) << elements << " elements";
  }
}

// A simply supported beam under a constant tension T:
// omega_n^2 = ((n pi / L)^4 EI + (n pi / L)^2 T) / rho A, exactly.
TEST(BeamModes, TensionStiffensAsTheClosedFormSays) {
  BeamSection s;
  s.length = 2.0, s.bending_stiffness_y = s.bending_stiffness_z = 150.0, s.mass_per_length = 0.6;
  s.elements = 16;
  const double T = 900.0;
  Structure beam = beam_structure(s);
  beam.K += geometric_stiffness(s, [&](double) { return T; });
  // Pinned at both ends: every translation and the twist held at each end.
  const std::vector<int> held = {0, 1, 2, 3, 6 * s.elements, 6 * s.elements + 1, 6 * s.elements + 2,
                                 6 * s.elements + 3};
  const StructuralModes modes = structural_modes(beam, held);
  for (int n = 1; n <= 3; ++n) {
    const double k = n * M_PI / s.length;
    const double f = std::sqrt((std::pow(k, 4) * s.bending_stiffness_y + k * k * T) / s.mass_per_length) / (2 * M_PI);
    // Both planes bend alike: the frequency appears twice.
    int found = 0;
    for (int m = 0; m < modes.frequency_hz.size(); ++m) found += std::abs(modes.frequency_hz[m] / f - 1) < 1e-4;
    EXPECT_EQ(found, 2) << "mode " << n << ", " << f << " Hz";
  }
}

// A cantilever spun at Omega about an axis through its root across it: the
// centrifugal tension rho A Omega^2 (L^2 - x^2) / 2 raises the bending
// frequencies out of the spin plane as omega^2 = omega_0^2 + K Omega^2 to
// first order, with K the Rayleigh quotient integral (L^2 - x^2) / 2
// phi'^2 dx / integral phi^2 dx of the exact cantilever shape phi (1.1933,
// evaluated here by fine quadrature, apart from the mesh; Southwell's
// 1.173 is a fit over a range of speeds, below it).
TEST(BeamModes, SpinStiffeningHasSouthwellsCoefficient) {
  BeamSection s;
  s.length = 1.0, s.bending_stiffness_y = s.bending_stiffness_z = 1.0, s.mass_per_length = 1.0;
  s.axial_stiffness = s.torsional_stiffness = 1e4;  // stretch and twist far above the first bending
  s.elements = 20;
  const double bL = 1.87510407, sigma = (std::cosh(bL) + std::cos(bL)) / (std::sinh(bL) + std::sin(bL));
  double tension_work = 0, mass = 0;
  const int steps = 200000;
  for (int i = 0; i < steps; ++i) {
    const double x = (i + 0.5) / steps, b = bL;
    const double phi = std::cosh(b * x) - std::cos(b * x) - sigma * (std::sinh(b * x) - std::sin(b * x));
    const double dphi = b * (std::sinh(b * x) + std::sin(b * x) - sigma * (std::cosh(b * x) - std::cos(b * x)));
    tension_work += (1 - x * x) / 2 * dphi * dphi / steps;
    mass += phi * phi / steps;
  }
  const double southwell = tension_work / mass;

  const Structure still = beam_structure(s);
  const Eigen::MatrixXd KG = geometric_stiffness(s, [&](double x) { return s.mass_per_length * (1 - x * x) / 2; });
  auto first_w = [&](double omega2) {
    Structure spun = still;
    spun.K += omega2 * KG;
    const StructuralModes modes = structural_modes(spun, spun.dofs_of({0}));
    return std::pow(2 * M_PI * modes.frequency_hz[0], 2);
  };
  const double d = 1e-3;
  EXPECT_NEAR((first_w(d) - first_w(0)) / d, southwell, 1e-4);
}

}  // namespace
}  // namespace unfurl::sim::flexible
