// A load's maximum between the steps. The integrator's steps sample a load
// that rises and falls between them (a flexible panel's hinge force rings
// at some hundred hertz), so the largest step value falls short of the
// maximum by about x'' h^2 / 8 and moves with where the steps land: with
// the units of the scene, the tolerance or the regulator's gains (the
// pantograph's peak hinge force 3.8e-5 of itself below a tight reference's,
// a generated flexible array's 6.7e-5 apart between two unit systems).
// Where a step value is a local maximum of the steps, the parabola through
// it and its neighbours puts the maximum at its vertex; that differs from
// the load's maximum between those steps by no more than the parabola differs
// from the load, O(h^3 x''') where the load is smooth (5e-7 and 4.6e-6 there).
#pragma once

#include <optional>

#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

class StepMaximum {
 public:
  // The load x at a step's end t. Where the step before was a local
  // maximum (above the one before it, not below this one), the vertex of
  // the parabola through the three; it lies between the outer two.
  std::optional<Peak> observe(double t, double x) {
    std::optional<Peak> vertex;
    if (count_ == 2 && x_[1] > x_[0] && x_[1] >= x) vertex = parabola_vertex(t, x);
    t_[0] = t_[1], x_[0] = x_[1];
    t_[1] = t, x_[1] = x;
    if (count_ < 2) ++count_;
    return vertex;
  }
  // The load's steps stop being one smooth function (a latch engaged, or
  // they stopped being tracked): the next maximum needs three new ones.
  void restart() { count_ = 0; }

 private:
  std::optional<Peak> parabola_vertex(double t, double x) const {
    const double h1 = t_[1] - t_[0], h2 = t - t_[1];
    if (!(h1 > 0 && h2 > 0)) return std::nullopt;
    const double d1 = (x_[1] - x_[0]) / h1, d2 = (x - x_[1]) / h2;
    const double c = (d2 - d1) / (h1 + h2);  // half the second derivative, < 0 here
    const double b = d1 + c * h1;            // the slope at t_[1]
    Peak vertex;
    vertex.value = x_[1] - b * b / (4 * c);
    vertex.t = t_[1] - b / (2 * c);
    return vertex;
  }
  double t_[2] = {0, 0}, x_[2] = {0, 0};
  int count_ = 0;
};

}  // namespace unfurl::sim
