// The classical fixed-step fourth-order Runge-Kutta method, for comparison.
// Steps sit on the grid t0 + k dt (a partial step reaches an event or the
// stop time); samples come from the cubic Hermite interpolant of each step,
// and a latch crossing inside a step is located on that interpolant and the
// step retaken up to it.
#pragma once

#include "integrator.hpp"

namespace unfurl {

class Rk4Integrator : public Integrator {
 public:
  Rk4Integrator(Dynamics& dynamics, const RunSettings& settings, double t0, const std::vector<double>& y0);

  StepOutcome step(double t_stop) override;
  void interpolate(double t, double* y) override;
  void restart(double t, const double* y) override;
  std::vector<int> roots() override { return roots_; }
  SolverStats stats() const override { return stats_; }
  double current_step() const override { return dt_; }

 private:
  bool take_step(double h);  // y0_, f0_ at t0_ -> y1_, f1_
  double earliest_crossing(std::vector<int>& which);

  Dynamics& dynamics_;
  double dt_;
  double t_grid0_;
  double t0_ = 0, t1_ = 0;  // the last step, [t0_, t1_]
  std::vector<double> y0_, f0_, y1_, f1_, k2_, k3_, k4_, tmp_;
  std::vector<double> s0_, s1_;  // switching values at the step ends
  std::vector<int> roots_;
  SolverStats stats_;
};

}  // namespace unfurl
