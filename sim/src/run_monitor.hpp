// What the simulation watches at the end of every step the integrator
// takes, not only at the samples: the peaks of the loads (a latch's shock
// lasts milliseconds), the loops' geometric gap (max_closure fails a run on
// it), and the step sizes away from restarts. Because it follows the steps,
// what it reports does not depend on the sampling interval; the peaks are
// interpolated between the steps (StepMaximum), so that they depend little
// on where the steps land.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "determinate_peak.hpp"
#include "step_maximum.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

class RunMonitor {
 public:
  explicit RunMonitor(Dynamics& dynamics);

  // At a step's end (t, y), latches as engaged there. Returns the largest
  // gap of any loop, radians or a distance over the mechanism's length;
  // nothing where the loads at y could not be evaluated.
  std::optional<double> observe(double t, const double* y);

  // Step-size bookkeeping: after each (re)start the step grows from a tiny
  // first step; until it stops growing the steps count as restart steps.
  void step_taken(double h);
  void restarted() { ramping_ = true, last_h_ = 0; }
  // Latches engaged at the step's end, before it is observed.
  void latched();

  // completed: the run went on to its end (not failed), so the loads it ends
  // on are as determinate as they were flagged (DeterminatePeak).
  RunPeaks peaks(bool completed) const;
  double min_step() const { return min_step_; }
  double min_step_after_restart() const { return min_step_after_restart_; }

 private:
  Dynamics& dynamics_;
  RunPeaks peaks_;
  std::vector<TrackedPeak> sensor_peaks_;
  std::vector<DeterminatePeak> hinge_force_, hinge_moment_;  // per joint
  std::vector<StepMaximum> latch_torque_between_, element_between_, sensor_between_;
  Loads loads_;
  std::vector<ClosureError> closure_;
  bool in_indeterminate_span_ = false;
  bool ramping_ = true;
  double last_h_ = 0;
  double min_step_ = std::numeric_limits<double>::infinity();
  double min_step_after_restart_ = std::numeric_limits<double>::infinity();
};

}  // namespace unfurl::sim
