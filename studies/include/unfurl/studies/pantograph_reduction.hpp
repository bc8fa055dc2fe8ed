// The one-degree-of-freedom reduction of the reference pantograph
// (SCENES.md), written from the geometry alone: on the lazy-tongs path
// q_i = c_i a with c = (-1, 2, -2, 2, 1, -2, 2, -2), each physical body turns
// by an absolute angle sigma a about x and its centre moves in the y-z
// plane; I(a) a'' + I'(a) a'^2 / 2 = -dV/da - sum c_i^2 c a'. It is the
// reference the tests and the speed benchmark measure angle errors against
// before the first latch.
#pragma once

#include <array>
#include <vector>

#include "unfurl/sim/trajectory.hpp"

namespace unfurl::studies {

struct PantographReduction {
  static constexpr std::array<double, 8> c{-1, 2, -2, 2, 1, -2, 2, -2};
  static constexpr double k = 0.10, damping = 0.02;
  static constexpr double a0 = 1.5607963267948966;  // pi/2 - 0.01, released at rest

  // I(a) and I'(a).
  void inertia(double a, double& I, double& dI) const;
  double potential(double a) const;
  double potential_gradient(double a) const;
  double damping_sum() const;
  // (a, a') -> (a', a'').
  std::array<double, 2> rate(const std::array<double, 2>& x) const;
};

// The reduction by RK4 at about 1e-5 s (its error far below the bounds it
// checks) through the given increasing times from t = 0, up to its latch
// (a = 0, located on the step's Hermite interpolant).
struct ReductionPath {
  std::vector<double> t, a;  // the given times before the latch, and a there
  double latch_time = 0;     // NaN when a never reaches 0 by the last time
};
ReductionPath integrate_reduction(const std::vector<double>& times);

// How far a run of the pantograph strays from the reduction: the largest
// |q_j - c_j a| over the joints j1..j8 at the samples before the
// reduction's latch, and where.
struct ReductionError {
  double angle = 0, at = 0;  // rad, s
  double latch_time = 0;     // the reduction's
};
ReductionError reduction_error(const sim::Trajectory& trajectory);

}  // namespace unfurl::studies
