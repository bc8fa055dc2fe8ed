// The pantograph of SCENES.md: latches, mirror symmetry, loop closure, and
// an independent one-degree-of-freedom reduction.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

// Everything from one run of the reference scene, shared by the tests.
class Pantograph : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(test::scene_file("pantograph"));
    run_ = new RunResult(simulate(*scene_, scene_->run));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete scene_;
  }
  static const Scene& scene() { return *scene_; }
  static const RunResult& run() { return *run_; }
  static double first_latch() {
    double t = INFINITY;
    for (const LatchEvent& e : run().trajectory.events) t = std::min(t, e.t);
    return t;
  }

 private:
  static Scene* scene_;
  static RunResult* run_;
};
Scene* Pantograph::scene_ = nullptr;
RunResult* Pantograph::run_ = nullptr;

TEST_F(Pantograph, RunsToTheEnd) {
  ASSERT_EQ(run().status, RunStatus::finished) << describe(run().failure);
  EXPECT_DOUBLE_EQ(run().trajectory.t_end(), 20.0);
}

TEST_F(Pantograph, AllEightLatchesEngageAtTheSameInstant) {
  const auto& events = run().trajectory.events;
  ASSERT_EQ(events.size(), 8u);
  double lo = INFINITY, hi = -INFINITY;
  for (const LatchEvent& e : events) {
    lo = std::min(lo, e.t);
    hi = std::max(hi, e.t);
  }
  EXPECT_LT(hi - lo, 1e-5) << "latch times spread over " << hi - lo << " s";
}

TEST_F(Pantograph, ChainsStayMirrorImagesUntilTheLatches) {
  // Chain B's joints are the negatives of chain A's: q5..q8 = -q1..-q4.
  double worst = 0;
  for (const Sample& s : run().trajectory.samples)
    if (s.t < first_latch())
      for (int j = 0; j < 4; ++j) worst = std::max(worst, std::abs(s.y[j] + s.y[4 + j]));
  EXPECT_LT(worst, 1e-6);
}

TEST_F(Pantograph, LatchesHoldEveryJointAtTheDeployedAngle) {
  // After the latches the array sits at q = 0, a branch point of the loops
  // where the chains need not stay mirror images (METHOD.md); each joint is
  // held within the static deflection of its latch under the spring
  // preload, k (pi/2) / k_L = 1.6e-4 rad, give or take the loop forces.
  const Sample& last = run().trajectory.samples.back();
  for (int j = 0; j < 8; ++j) EXPECT_LT(std::abs(last.y[j]), 5e-4) << "joint " << j + 1;
}

TEST_F(Pantograph, LoopsStayClosedOverTheWholeRun) {
  const RunSummary s = summarize(scene(), run());
  EXPECT_LT(s.max_closure_m, 1e-7);
  EXPECT_LT(s.max_closure_rad, 1e-6);
}

// The same deployment by another way to the same equations: latch times
// within the accuracy asked of them against the reduction (1e-5 s; GMRES's
// inexact Newton steps move them by 2e-6 s, the sparse solver by 1e-9 s),
// and the loops as closed.
void expect_same_deployment(const RunResult& a, const RunResult& b, const Scene& scene) {
  ASSERT_EQ(b.status, RunStatus::finished) << describe(b.failure);
  ASSERT_EQ(a.trajectory.events.size(), b.trajectory.events.size());
  for (std::size_t k = 0; k < a.trajectory.events.size(); ++k)
    EXPECT_NEAR(a.trajectory.events[k].t, b.trajectory.events[k].t, 1e-5);
  EXPECT_LT(summarize(scene, b).max_closure_m, 1e-7);
}

TEST_F(Pantograph, SparseGainSolverGivesTheSameDeployment) {
  const Scene sparse = test::scene_file("pantograph", {{"regulator.solver", "sparse"}});
  expect_same_deployment(run(), simulate(sparse, sparse.run), sparse);
}

TEST_F(Pantograph, KrylovNewtonSolverGivesTheSameDeployment) {
  const Scene krylov = test::scene_file("pantograph", {{"run.linear_solver", "krylov"}});
  expect_same_deployment(run(), simulate(krylov, krylov.run), krylov);
}

// The one-degree-of-freedom reduction of SCENES.md, written from the
// geometry alone: on the lazy-tongs path q_i = c_i a with
// c = (-1, 2, -2, 2, 1, -2, 2, -2), each physical body turns by an absolute
// angle sigma a about x and its centre moves in the y-z plane.
struct Reduction {
  static constexpr std::array<double, 8> c{-1, 2, -2, 2, 1, -2, 2, -2};
  static constexpr double k = 0.10, damping = 0.02;

  struct Link {
    double sigma;      // absolute angle = sigma a
    double l, p;       // half-length and pivot-line offset
    double mass, Ixx;
  };
  // Chain A and chain B (its mirror image: offsets and angles negated).
  std::array<Link, 4> chain(double mirror) const {
    return {{{-mirror, 0.30, 0, 1.2, 0.03606},
             {mirror, 0.60, mirror * 0.03, 4.0, 0.4802},
             {-mirror, 0.60, -mirror * 0.06, 4.0, 0.4802},
             {mirror, 0.60, mirror * 0.09, 4.0, 0.4802}}};
  }

  // R(theta) (y, z) and its derivatives in theta.
  static std::array<double, 2> rotate(double th, double y, double z, int derivative) {
    const double cs = std::cos(th), sn = std::sin(th);
    switch (derivative % 4) {
      case 0: return {y * cs - z * sn, y * sn + z * cs};
      case 1: return {-y * sn - z * cs, y * cs - z * sn};
      case 2: return {-y * cs + z * sn, -y * sn - z * cs};
      default: return {y * sn + z * cs, -y * cs + z * sn};
    }
  }

  // I(a) and I'(a) from the centres' velocities dr/da and d2r/da2.
  void inertia(double a, double& I, double& dI) const {
    I = dI = 0;
    for (double mirror : {1.0, -1.0}) {
      // Walk the chain: hinge -> centre -> next hinge, summing derivatives.
      std::array<double, 2> hinge_d1{0, 0}, hinge_d2{0, 0};
      for (const Link& L : chain(mirror)) {
        std::array<double, 2> d1 = hinge_d1, d2 = hinge_d2;
        // centre = hinge - R(theta) (-l, p) = hinge + R(theta) (l, -p)
        const auto r1 = rotate(L.sigma * a, L.l, -L.p, 1);
        const auto r2 = rotate(L.sigma * a, L.l, -L.p, 2);
        for (int k2 = 0; k2 < 2; ++k2) {
          d1[k2] += L.sigma * r1[k2];
          d2[k2] += L.sigma * L.sigma * r2[k2];
        }
        I += L.mass * (d1[0] * d1[0] + d1[1] * d1[1]) + L.Ixx * L.sigma * L.sigma;
        dI += 2 * L.mass * (d1[0] * d2[0] + d1[1] * d2[1]);
        // next hinge = centre + R(theta) (l, p)
        const auto h1 = rotate(L.sigma * a, L.l, L.p, 1);
        const auto h2 = rotate(L.sigma * a, L.l, L.p, 2);
        for (int k2 = 0; k2 < 2; ++k2) {
          hinge_d1[k2] = d1[k2] + L.sigma * h1[k2];
          hinge_d2[k2] = d2[k2] + L.sigma * L.sigma * h2[k2];
        }
      }
    }
  }

  double potential_gradient(double a) const {
    double dV = 0;
    for (double ci : c) dV += k * ci * (ci * a + (ci > 0 ? 1 : -1) * M_PI / 2);
    return dV;
  }
  double potential(double a) const {
    double V = 0;
    for (double ci : c) V += 0.5 * k * std::pow(ci * a + (ci > 0 ? 1 : -1) * M_PI / 2, 2);
    return V;
  }
  double damping_sum() const {
    double s = 0;
    for (double ci : c) s += damping * ci * ci;
    return s;
  }

  // (a, a') -> (a', a''): I a'' + I' a'^2 / 2 = -dV/da - sum c_i^2 c a'.
  std::array<double, 2> rate(const std::array<double, 2>& x) const {
    double I, dI;
    inertia(x[0], I, dI);
    return {x[1], (-potential_gradient(x[0]) - damping_sum() * x[1] - 0.5 * dI * x[1] * x[1]) / I};
  }
};

TEST(PantographReduction, MatchesTheMethodsFigures) {
  const Reduction r;
  double I, dI;
  const double a0 = M_PI / 2 - 0.01;
  r.inertia(a0, I, dI);
  EXPECT_NEAR(I, 164.45, 0.01);
  r.inertia(0, I, dI);
  EXPECT_NEAR(I, 3.270, 0.001);
  EXPECT_NEAR(r.potential(a0), 7.58624, 1e-5);
}

TEST_F(Pantograph, AgreesWithTheOneDegreeOfFreedomReduction) {
  // Integrate the reduction with RK4 at about 1e-5 s (its error is far below
  // the bounds) from sample to sample, compare at every sample before the
  // first latch, and locate its latch (a = 0) on the step's Hermite
  // interpolant.
  const Reduction r;
  auto rk4_step = [&](const std::array<double, 2>& x, double h) {
    const auto k1 = r.rate(x);
    const auto k2 = r.rate({x[0] + h / 2 * k1[0], x[1] + h / 2 * k1[1]});
    const auto k3 = r.rate({x[0] + h / 2 * k2[0], x[1] + h / 2 * k2[1]});
    const auto k4 = r.rate({x[0] + h * k3[0], x[1] + h * k3[1]});
    return std::array<double, 2>{x[0] + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
                                 x[1] + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])};
  };
  std::array<double, 2> x{M_PI / 2 - 0.01, 0};
  double latch_time = NAN, worst = 0, worst_t = 0;
  const auto& samples = run().trajectory.samples;
  const double t_first = first_latch();
  for (std::size_t i = 1; i < samples.size() && std::isnan(latch_time); ++i) {
    const double t0 = samples[i - 1].t;
    const int steps = static_cast<int>(std::ceil((samples[i].t - t0) / 1e-5 - 1e-9));
    const double h = (samples[i].t - t0) / steps;
    for (int k = 0; k < steps && std::isnan(latch_time); ++k) {
      const std::array<double, 2> xn = rk4_step(x, h);
      if (xn[0] <= 0) {
        double lo = 0, hi = 1;
        for (int it = 0; it < 60; ++it) {
          const double s = 0.5 * (lo + hi);
          const double a = (1 + 2 * s) * (1 - s) * (1 - s) * x[0] + s * (1 - s) * (1 - s) * h * x[1] +
                           s * s * (3 - 2 * s) * xn[0] + s * s * (s - 1) * h * xn[1];
          (a > 0 ? lo : hi) = s;
        }
        latch_time = t0 + (k + hi) * h;
      }
      x = xn;
    }
    if (!std::isnan(latch_time) || samples[i].t >= t_first) break;
    for (int j = 0; j < 8; ++j) {
      const double err = std::abs(samples[i].y[j] - Reduction::c[j] * x[0]);
      if (err > worst) worst = err, worst_t = samples[i].t;
    }
  }
  ASSERT_FALSE(std::isnan(latch_time));
  EXPECT_LT(worst, 3e-7) << "largest joint-angle difference " << worst << " rad at t = " << worst_t;
  for (const LatchEvent& e : run().trajectory.events)
    EXPECT_NEAR(e.t, latch_time, 1e-5) << scene().model.joints[e.joint].name;
  std::printf("reduction latch time %.9f s; largest angle difference before it %.3g rad at t = %.3f s\n",
              latch_time, worst, worst_t);
}

}  // namespace
}  // namespace unfurl
