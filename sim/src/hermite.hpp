// Cubic Hermite interpolation on [t0, t1] from the values y and slopes f at
// both ends: the dense output of RK4 and the renderer's interpolation of a
// recorded trajectory (q with its rates dq).
#pragma once

namespace unfurl::sim {

struct Hermite {
  double t0, t1;

  // y(t).
  double value(double y0, double f0, double y1, double f1, double t) const {
    const double h = t1 - t0, s = (t - t0) / h;
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    return h00 * y0 + h10 * h * f0 + h01 * y1 + h11 * h * f1;
  }

  // dy/dt(t).
  double rate(double y0, double f0, double y1, double f1, double t) const {
    const double h = t1 - t0, s = (t - t0) / h;
    const double d00 = 6 * s * (s - 1), d10 = (1 - s) * (1 - 3 * s);
    const double d01 = -d00, d11 = s * (3 * s - 2);
    return (d00 * y0 + d01 * y1) / h + d10 * f0 + d11 * f1;
  }
};

}  // namespace unfurl::sim
