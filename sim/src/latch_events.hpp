// Latch events on the integrator's last step. A latch engages the first
// time its joint reaches the deployed position: a root of its switching
// function s = side (q - position), which the integrators' root finding
// locates when s changes sign between step ends. Two things it cannot see
// are handled here, on the step's interpolant:
// - simultaneous latches: after the first root, every other latch whose
//   crossing follows within `event_window` seconds (and inside the step)
//   joins one group, each at its own root found by bisection; the group
//   costs one restart, at its last root;
// - a graze: s dips to zero and back inside one step, so it has the same
//   sign at both ends. It is found where ds/dt of the interpolant turns from
//   falling to rising inside the step with s positive at both ends: the
//   minimum (bisection on ds/dt) is checked, and if s <= 0 there the first
//   crossing before it is the root. A crossing missed at the very end of a
//   step (s exactly zero at a stop time) is found the same way. That search
//   interpolates the whole state some 60 times, so it is made only where a
//   bound on s over the step (step_polynomial_bound.hpp) lets s come near
//   zero: with many latches ringing, a search for each on every step would
//   cost O(latches x state) per step.
#pragma once

#include <optional>
#include <vector>

#include "step_polynomial_bound.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/integrator.hpp"

namespace unfurl::sim {

struct LatchRoot {
  int latch = 0;
  double t = 0;
};

struct LatchGroup {
  std::vector<LatchRoot> roots;  // empty: no latch engages on this step
  double t_restart = 0;          // the last of the roots
  bool empty() const { return roots.empty(); }
};

class LatchEvents {
 public:
  LatchEvents(Dynamics& dynamics, double window);

  // The latches that engage on the integrator's last step, given the step's
  // outcome (a root return names the first).
  LatchGroup find(Integrator& integrator, const StepOutcome& step);

  // Engages the group at its restart time; y is the state there. A latch
  // whose root came earlier in the window adds the impulse its torque would
  // have given since (trapezoidal rule over its root and the restart) to
  // the joint's momentum, so each acts from its own root.
  void engage(const LatchGroup& group, Integrator& integrator, double* y);

  long grazes() const { return grazes_; }

 private:
  double switching(int l, const double* y) const;
  double switching_rate(int l, const double* ydot) const;
  double switching_at(Integrator& integrator, int l, double t);
  // The root of latch l's switching function on [lo, hi], s(lo) > 0 >= s(hi).
  double bisect(Integrator& integrator, int l, double lo, double hi);
  // The root of a graze of latch l inside [lo, hi], or a negative value.
  double graze(Integrator& integrator, int l, double lo, double hi);
  // Whether latch l's s may reach zero inside the step [lo, hi] (false
  // only where it cannot).
  bool may_reach_zero(Integrator& integrator, int l, double lo, double hi);
  double latch_torque(int l, double t, const double* y);

  Dynamics& dynamics_;
  double window_;
  long grazes_ = 0;
  std::vector<double> y_, ydot_, rate_lo_, rate_hi_, y_lo_, y_hi_;
  std::optional<StepPolynomialBound> bound_;
  std::vector<std::vector<double>> at_nodes_;  // the step's states at the bound's nodes, once per step
  bool nodes_ready_ = false;
};

}  // namespace unfurl::sim
