// A torsion (or linear) spring's measured curve: torque against angle from
// a test, as a table of points, interpolated by a monotone cubic.
#pragma once

#include <vector>

namespace unfurl::sim {

// tau(q) through the points (q_k, tau_k), q increasing: piecewise cubic
// Hermite with Fritsch-Carlson slopes, so the curve is C1 and never
// overshoots the data (monotone between monotone points, no wiggles a
// spline would add between test points). Beyond the first and last points
// it continues as the straight line of the end slope.
class SpringCurve {
 public:
  // Throws std::invalid_argument unless there are >= 2 points with strictly
  // increasing angles.
  SpringCurve(std::vector<double> q, std::vector<double> tau);

  double torque(double q) const;
  // d tau / dq: the spring's stiffness is its negative.
  double slope(double q) const;
  // The potential V(q) = -integral of tau from the first point to q (J).
  double energy(double q) const;

  const std::vector<double>& angles() const { return q_; }
  const std::vector<double>& torques() const { return tau_; }

 private:
  int segment(double q) const;       // k with q_k <= q < q_{k+1}, clamped
  std::vector<double> q_, tau_, m_;  // points and slopes at them
  std::vector<double> work_;         // integral of tau from q_0 to q_k
};

}  // namespace unfurl::sim
