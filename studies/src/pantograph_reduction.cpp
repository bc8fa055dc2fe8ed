#include "unfurl/studies/pantograph_reduction.hpp"

#include <cmath>
#include <limits>

namespace unfurl::studies {

namespace {

struct Link {
  double sigma;  // absolute angle = sigma a
  double l, p;   // half-length and pivot-line offset
  double mass, Ixx;
};

// Chain A and chain B (its mirror image: offsets and angles negated).
std::array<Link, 4> chain(double mirror) {
  return {{{-mirror, 0.30, 0, 1.2, 0.03606},
           {mirror, 0.60, mirror * 0.03, 4.0, 0.4802},
           {-mirror, 0.60, -mirror * 0.06, 4.0, 0.4802},
           {mirror, 0.60, mirror * 0.09, 4.0, 0.4802}}};
}

// R(theta) (y, z) and its derivatives in theta.
std::array<double, 2> rotate(double th, double y, double z, int derivative) {
  const double cs = std::cos(th), sn = std::sin(th);
  switch (derivative % 4) {
    case 0: return {y * cs - z * sn, y * sn + z * cs};
    case 1: return {-y * sn - z * cs, y * cs - z * sn};
    case 2: return {-y * cs + z * sn, -y * sn - z * cs};
    default: return {y * sn + z * cs, -y * cs + z * sn};
  }
}

}  // namespace

void PantographReduction::inertia(double a, double& I, double& dI) const {
  // From the centres' velocities dr/da and d2r/da2, walking each chain:
  // hinge -> centre -> next hinge.
  I = dI = 0;
  for (double mirror : {1.0, -1.0}) {
    std::array<double, 2> hinge_d1{0, 0}, hinge_d2{0, 0};
    for (const Link& L : chain(mirror)) {
      std::array<double, 2> d1 = hinge_d1, d2 = hinge_d2;
      // centre = hinge + R(theta) (l, -p)
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

double PantographReduction::potential_gradient(double a) const {
  double dV = 0;
  for (double ci : c) dV += k * ci * (ci * a + (ci > 0 ? 1 : -1) * M_PI / 2);
  return dV;
}

double PantographReduction::potential(double a) const {
  double V = 0;
  for (double ci : c) V += 0.5 * k * std::pow(ci * a + (ci > 0 ? 1 : -1) * M_PI / 2, 2);
  return V;
}

double PantographReduction::damping_sum() const {
  double s = 0;
  for (double ci : c) s += damping * ci * ci;
  return s;
}

std::array<double, 2> PantographReduction::rate(const std::array<double, 2>& x) const {
  double I, dI;
  inertia(x[0], I, dI);
  return {x[1], (-potential_gradient(x[0]) - damping_sum() * x[1] - 0.5 * dI * x[1] * x[1]) / I};
}

ReductionPath integrate_reduction(const std::vector<double>& times) {
  const PantographReduction r;
  auto rk4_step = [&](const std::array<double, 2>& x, double h) {
    const auto k1 = r.rate(x);
    const auto k2 = r.rate({x[0] + h / 2 * k1[0], x[1] + h / 2 * k1[1]});
    const auto k3 = r.rate({x[0] + h / 2 * k2[0], x[1] + h / 2 * k2[1]});
    const auto k4 = r.rate({x[0] + h * k3[0], x[1] + h * k3[1]});
    return std::array<double, 2>{x[0] + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
                                 x[1] + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])};
  };
  ReductionPath path;
  path.latch_time = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 2> x{PantographReduction::a0, 0};
  double t = 0;
  for (double target : times) {
    const int steps = std::max(1, static_cast<int>(std::ceil((target - t) / 1e-5 - 1e-9)));
    const double h = (target - t) / steps;
    for (int k = 0; k < steps && target > t; ++k) {
      const std::array<double, 2> xn = rk4_step(x, h);
      if (xn[0] <= 0) {
        double lo = 0, hi = 1;
        for (int it = 0; it < 60; ++it) {
          const double s = 0.5 * (lo + hi);
          const double a = (1 + 2 * s) * (1 - s) * (1 - s) * x[0] + s * (1 - s) * (1 - s) * h * x[1] +
                           s * s * (3 - 2 * s) * xn[0] + s * s * (s - 1) * h * xn[1];
          (a > 0 ? lo : hi) = s;
        }
        path.latch_time = t + (k + hi) * h;
        return path;
      }
      x = xn;
    }
    t = std::max(t, target);
    path.t.push_back(target);
    path.a.push_back(x[0]);
  }
  return path;
}

ReductionError reduction_error(const sim::Trajectory& trajectory) {
  std::vector<double> times;
  for (const sim::Sample& s : trajectory.samples) times.push_back(s.t);
  const ReductionPath path = integrate_reduction(times);
  ReductionError error;
  error.latch_time = path.latch_time;
  // Before either latch: after the run's, its angles are held by latches.
  const double first_latch = trajectory.events.empty() ? path.latch_time : trajectory.events.front().t;
  for (std::size_t i = 0; i < path.t.size() && !(path.t[i] >= first_latch); ++i)
    for (int j = 0; j < 8; ++j) {
      const double e = std::abs(trajectory.samples[i].y[trajectory.layout.q() + j] - PantographReduction::c[j] * path.a[i]);
      if (e > error.angle) error.angle = e, error.at = path.t[i];
    }
  return error;
}

}  // namespace unfurl::studies
