// The four cubic Hermite shape functions of an element of length h, the
// interpolation of a Euler-Bernoulli beam and, as products in x and y, of
// the Bogner-Fox-Schmit plate: value and slope at each end.
#pragma once

#include <array>

namespace unfurl::sim::flexible {

// At xi = x / h in [0, 1]: N (value at 0, slope at 0, value at 1, slope at
// 1) and its first and second derivatives in x.
struct CubicHermiteShape {
  std::array<double, 4> N, dN, ddN;

  CubicHermiteShape(double xi, double h) {
    const double x2 = xi * xi, x3 = x2 * xi;
    N = {1 - 3 * x2 + 2 * x3, h * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, h * (x3 - x2)};
    dN = {(-6 * xi + 6 * x2) / h, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / h, 3 * x2 - 2 * xi};
    ddN = {(-6 + 12 * xi) / (h * h), (-4 + 6 * xi) / h, (6 - 12 * xi) / (h * h), (6 * xi - 2) / h};
  }
};

// Four-point Gauss-Legendre on [0, 1]: exact to degree 7, so for products
// of two cubics (the mass) and everything below.
struct GaussFour {
  static constexpr std::array<double, 4> x = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                              0.9305681557970263};
  static constexpr std::array<double, 4> w = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                              0.1739274225687269};
};

}  // namespace unfurl::sim::flexible
