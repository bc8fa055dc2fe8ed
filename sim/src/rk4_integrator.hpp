// The classical fixed-step fourth-order Runge-Kutta method, for comparison.
// Steps sit on the grid t0 + k dt (a partial step reaches the stop time);
// samples and events come from the cubic Hermite interpolant of each step,
// whose error at a point, O(dt^4), matches the method's global order. A step
// in which a latch's switching function crosses zero is reported as a root
// at the earliest crossing; the simulation restarts the method there.
#pragma once

#include "unfurl/sim/integrator.hpp"

namespace unfurl::sim {

class Rk4Integrator : public Integrator {
 public:
  Rk4Integrator(Dynamics& dynamics, const RunSettings& settings, double t0, const std::vector<double>& y0);

  StepOutcome step(double t_stop) override;
  double span_begin() const override { return t0_; }
  double span_end() const override { return t1_; }
  void interpolate(double t, double* y) override;
  void interpolate_rate(double t, double* ydot) override;
  int interpolation_degree() const override { return 3; }  // the cubic Hermite of each step
  void restart(double t, const double* y) override;
  std::vector<int> roots() override { return roots_; }
  SolverStats stats() const override { return stats_; }
  double current_step() const override { return dt_; }
  double last_step() const override { return t1_ - t0_; }

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

}  // namespace unfurl::sim
