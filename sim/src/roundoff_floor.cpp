#include "unfurl/sim/roundoff_floor.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim {

double roundoff_floor(Dynamics& dynamics, double t, const std::vector<double>& y) {
  const std::size_t n = y.size();
  const std::vector<double>& scale = dynamics.state_scale();
  const double rate = dynamics.scales().rate;
  // Far above the spacing of doubles and far below any physics: the
  // curvature's part, e^2 |f''|, is some 1e-24 of f.
  constexpr double e = 1e-12;
  std::vector<double> y1(n), y2(n), f0(n), f1(n), f2(n);
  if (!dynamics.rhs(t, y.data(), f0.data())) return 0;
  double floor = 0;
  for (int direction = 1; direction <= 3; ++direction) {
    for (std::size_t k = 0; k < n; ++k) {
      y1[k] = y[k] + e * scale[k] * std::cos(direction * (1.0 + 3.0 * k));
      y2[k] = y[k] + 2 * (y1[k] - y[k]);
    }
    if (!dynamics.rhs(t, y1.data(), f1.data()) || !dynamics.rhs(t, y2.data(), f2.data())) return 0;
    double sum = 0;
    for (std::size_t k = 0; k < n; ++k) sum += std::pow((f2[k] - 2 * f1[k] + f0[k]) / (scale[k] * rate), 2);
    floor = std::max(floor, std::sqrt(sum / n));
  }
  return floor;
}

}  // namespace unfurl::sim
