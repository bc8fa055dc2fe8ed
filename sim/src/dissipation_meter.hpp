// The work the force elements (dampers, friction, engaged latches) take out
// of a run, and the work the drivers put in, integrated along the
// integrator's steps so the energy balance (EnergyParts::balance) can be
// checked to the run's own accuracy.
#pragma once

#include <vector>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/integrator.hpp"

namespace unfurl::sim {

class DissipationMeter {
 public:
  DissipationMeter(Dynamics& dynamics, double t0);

  // Adds the work over [t_, t] by three-point Gauss-Legendre quadrature of
  // the dissipated power (and the drivers' power) on the integrator's
  // interpolant of the state and the joint rates.
  // [t_, t] must lie within the step the integrator has just taken, and the
  // latch states must be those of that step (advance before engaging).
  void advance(Integrator& integrator, double t);
  double work() const { return work_; }
  double drive_work() const { return drive_work_; }

 private:
  Dynamics& dynamics_;
  bool dissipative_;
  bool driven_;
  double t_;
  double work_ = 0;
  double drive_work_ = 0;
  std::vector<double> y_, ydot_;
};

}  // namespace unfurl::sim
