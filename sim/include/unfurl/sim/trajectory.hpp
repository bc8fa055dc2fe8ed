// The recorded run: states sampled at fixed times, what was derived from
// them, and the latch events. Readers (renderer, plots, files) interpolate
// it; they never call the solver.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/energy.hpp"
#include "unfurl/sim/force_element.hpp"
#include "unfurl/sim/loads.hpp"
#include "unfurl/sim/loop.hpp"
#include "unfurl/sim/momentum.hpp"
#include "unfurl/sim/state_layout.hpp"

namespace unfurl::sim {

struct Sample {
  double t = 0;
  std::vector<double> y;             // the full state
  std::vector<double> q_dot;         // q' (a one-coordinate joint's rate)
  std::vector<ClosureError> closure; // geometric gap per loop
  EnergyParts energy;
  SystemMomentum momentum;
  Loads loads;
};

struct LatchEvent {
  double t = 0;
  int latch = 0;
  int joint = 0;
};

struct Trajectory {
  StateLayout layout;
  std::vector<LoopComponent> loop_components;  // what Loads::loop_force holds
  std::vector<LoadColumn> load_columns;        // what Loads::element holds
  std::vector<LoadColumn> sensor_columns;      // what Loads::sensor holds
  std::vector<Sample> samples;
  std::vector<LatchEvent> events;

  bool empty() const { return samples.empty(); }
  double t_begin() const { return samples.front().t; }
  double t_end() const { return samples.back().t; }
  // Joint coordinates at time t (clamped to the recorded span), by cubic
  // Hermite interpolation of q with its rates dq.
  void coordinates_at(double t, std::vector<double>& q) const;
  // The last sample at or before t (the first before the run): loads are
  // not interpolated, since a latch changes them within a sample interval.
  // Needs a sample.
  const Sample& sample_at(double t) const;
};

}  // namespace unfurl::sim
