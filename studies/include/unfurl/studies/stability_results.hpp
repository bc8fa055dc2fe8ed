// Running a stability case and what it measured: status, work, energy,
// loop gap, latches, and notes (branches taken, closing time, an energy
// that rose).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/stability_cases.hpp"

namespace unfurl::studies {

struct StabilityResult {
  StabilityCase spec;
  sim::RunStatus status = sim::RunStatus::finished;
  std::string failed_check, failure;
  double t_reached = 0, wall_time_s = 0, min_step = 0;
  long steps = 0, rhs_calls = 0;
  int bodies = 0, loop_components = 0;
  double energy_initial = 0, energy_final = 0;
  double energy_drift = std::numeric_limits<double>::quiet_NaN();  // max |E - E0| / |E0| (conservative cases)
  double max_closure_gap = 0, max_closure_angle = 0;
  int latches_engaged = 0, latches_total = 0;
  bool energy_rose = false;        // a passive, non-conservative run that gained energy: not physical
  std::vector<std::string> notes;  // branches, closing time
  sim::Trajectory trajectory;      // kept for the conservative (long) run's plot
};

StabilityResult run_stability_case(const StabilityCase& c);

}  // namespace unfurl::studies
