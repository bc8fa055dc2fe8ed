// The figures a user reads off a run: latch times, the largest geometric
// loop gap, energy at both ends, the final state.
#pragma once

#include <string>
#include <vector>

#include "simulation.hpp"

namespace unfurl {

struct RunSummary {
  std::vector<std::pair<std::string, double>> latch_times;  // joint name, time
  std::vector<std::string> unlatched;                       // joints whose latch never engaged
  double max_closure_m = 0;    // the largest gap over loops and samples
  double max_closure_rad = 0;
  double max_closure_m_before_latch = 0;  // the same up to the first latch
  double max_closure_rad_before_latch = 0;
  double energy_initial = 0;
  double energy_final = 0;
  double t_reached = 0;
  std::vector<std::pair<std::string, double>> final_q;  // joint name, q
};

RunSummary summarize(const Scene& scene, const RunResult& result);

}  // namespace unfurl
