// Physics against analytic solutions and invariants.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

// K(k), the complete elliptic integral of the first kind, by the AGM.
double elliptic_K(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  while (std::abs(a - b) > 1e-16 * a) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return M_PI / (2 * a);
}

// Times where q falls through zero, located on the cubic Hermite
// interpolant between samples.
std::vector<double> downward_zero_crossings(const sim::Trajectory& tr) {
  std::vector<double> times;
  for (std::size_t i = 1; i < tr.samples.size(); ++i) {
    const sim::Sample &a = tr.samples[i - 1], &b = tr.samples[i];
    if (!(a.y[0] > 0 && b.y[0] <= 0)) continue;
    double lo = a.t, hi = b.t;
    std::vector<double> q;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      tr.coordinates_at(mid, q);
      (q[0] > 0 ? lo : hi) = mid;
    }
    times.push_back(0.5 * (lo + hi));
  }
  return times;
}

TEST(Pendulum, PeriodAtLargeAmplitudeMatchesTheEllipticIntegral) {
  const sim::Scene scene = test::scene_file("pendulum", {{"run.sample", "0.001"}});
  const sim::Body& bob = scene.model.bodies[0];
  const double I = bob.inertia_com(0, 0) + bob.mass * bob.com.squaredNorm();
  const double d = bob.com.norm(), g = 9.81, q0 = scene.q0[0];
  const double period = 4 * std::sqrt(I / (bob.mass * g * d)) * elliptic_K(std::sin(q0 / 2));

  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const auto crossings = downward_zero_crossings(run.trajectory);
  ASSERT_GE(crossings.size(), 3u);
  // Successive downward crossings are one period apart, and the first is a
  // quarter period after release.
  EXPECT_NEAR(crossings[0], period / 4, 1e-7);
  for (std::size_t i = 1; i < crossings.size(); ++i)
    EXPECT_NEAR(crossings[i] - crossings[i - 1], period, 1e-7) << "period " << i;
}

// Conservative scenes keep their energy: the drift is bounded by the
// tolerance (a BDF run's global error is a modest multiple of rtol) and
// shrinks when the tolerance is tightened.
double energy_drift(sim::Scene scene, double rtol) {
  scene.run.rtol = rtol;
  scene.run.atol = rtol / 100;
  const sim::RunResult run = sim::simulate(scene, scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  const double E0 = run.trajectory.samples.front().energy.total();
  double drift = 0, scale = 0;
  for (const sim::Sample& s : run.trajectory.samples) {
    drift = std::max(drift, std::abs(s.energy.total() - E0));
    scale = std::max(scale, s.energy.kinetic);
  }
  return drift / scale;
}

void expect_energy_kept(const sim::Scene& scene) {
  const double rtol = 1e-8;
  const double drift = energy_drift(scene, rtol);
  EXPECT_LT(drift, 1000 * rtol) << scene.name << ": relative drift " << drift << " at rtol " << rtol;
  EXPECT_LT(energy_drift(scene, rtol / 100), drift / 10) << scene.name;
}

TEST(Energy, PendulumKeepsItsEnergy) {
  expect_energy_kept(test::scene_file("pendulum"));
}

TEST(Energy, DoublePendulumKeepsItsEnergy) {
  expect_energy_kept(test::scene_file("double_pendulum"));
}

TEST(Energy, UndampedZfoldWithoutLatchesKeepsItsEnergy) {
  // The z-fold's springs without damping and latches: a conservative chain.
  std::vector<sim::Override> o{{"latches", "[]"}, {"run.t_end", "10"}};
  for (int j = 0; j < 4; ++j) o.push_back({"springs." + std::to_string(j) + ".damping", "0"});
  expect_energy_kept(test::scene_file("zfold", o));
}

TEST(Energy, ConservativeSpinningBaseKeepsItsHamiltonian) {
  // A steadily spinning base (no gravity): the Jacobi integral H is
  // conserved; check it through p and q' (H = p.q'/2 - T0 + V changes only
  // by integration error) via the kinetic energy relative to the base.
  const sim::Scene scene = test::scene_file("zfold", {{"latches", "[]"},
                                                      {"springs.0.damping", "0"},
                                                      {"springs.1.damping", "0"},
                                                      {"springs.2.damping", "0"},
                                                      {"springs.3.damping", "0"},
                                                      {"base.velocity", "[0, 0, 0, 0, 0.2, 0]"},
                                                      {"run.t_end", "5"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  // H = p.dq - L, with L = T - V; T and V from the observation.
  auto H = [&](const sim::Sample& s) {
    double pdq = 0;
    for (int c = 0; c < scene.model.nq; ++c) pdq += s.y[scene.model.nq + c] * s.q_dot[c];
    return pdq - s.energy.kinetic + s.energy.springs;
  };
  const double H0 = H(run.trajectory.samples.front());
  double drift = 0;
  for (const sim::Sample& s : run.trajectory.samples) drift = std::max(drift, std::abs(H(s) - H0));
  EXPECT_LT(drift, 1e-6 * std::abs(H0));
}

}  // namespace
}  // namespace unfurl
