// What a torque margin analysis gives (torque_margin.hpp computes it): per
// driven joint, the torques and the motorization factor along the run and
// over the whole travel. Plain data, for the summary, files and plots.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/torque_margin_factors.hpp"

namespace unfurl::sim {

// The torques at one point of a joint's travel (each >= 0: a driving or a
// resisting magnitude, N m or N), and the motorization factor there.
struct TorqueMarginPoint {
  double t = std::numeric_limits<double>::quiet_NaN();  // the run's time; NaN quasi-statically
  double q = 0;
  double drive = 0, spring = 0, friction = 0, damping = 0, harness = 0, inertia = 0;
  double factor = std::numeric_limits<double>::infinity();  // MoF
};

struct JointTorqueMargin {
  std::string joint;
  std::vector<TorqueMarginPoint> run;           // along the run, before the latch
  std::vector<TorqueMarginPoint> quasi_static;  // over the whole travel
  // The smallest MoF of each and where (index into the list; -1 if empty).
  int worst_run = -1, worst_quasi_static = -1;
  double worst() const;  // the smaller of the two
  bool passes(const TorqueMarginFactors& f) const { return worst() >= f.required; }
};

}  // namespace unfurl::sim
