// The lumped beam (`unfurl generate beam`, studies::generate_beam): rigid
// segments with bending springs against the Euler-Bernoulli cantilever's
// closed-form frequencies, converging at second order; and Simo and
// Vu-Quoc's spin-up, driven at the hub past the beam's first frequency:
// a chain of rigid bodies keeps the centrifugal stiffening, so its tip
// deflection stays bounded and converges as the segments shrink.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "unfurl/sim/modes.hpp"
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

}  // namespace
}  // namespace unfurl
