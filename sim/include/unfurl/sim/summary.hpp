// The figures a user reads off a run: latch times, the largest geometric
// loop gap, the peak loads, energy at both ends, the final state. Gaps and
// loads are over every step the integrator took (RunPeaks), not only the
// samples.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"

namespace unfurl {

struct RunSummary {
  std::vector<std::pair<std::string, double>> latch_times;  // joint name, time
  std::vector<std::string> unlatched;                       // joints whose latch never engaged
  double max_closure_m = 0;    // the largest gap over loops and steps
  double max_closure_rad = 0;
  double max_closure_m_before_latch = 0;  // the same up to the first latch
  double max_closure_rad_before_latch = 0;
  struct NamedPeak {
    std::string joint;
    Peak peak;
  };
  std::vector<NamedPeak> latch_peak_torque;  // per latch
  std::vector<NamedPeak> hinge_peak_force;   // per joint
  std::vector<NamedPeak> hinge_peak_moment;  // per joint
  double energy_initial = 0;
  double energy_final = 0;
  double energy_dissipated = 0;  // by dampers, friction and latches up to t_reached
  double t_reached = 0;
  std::vector<std::pair<std::string, double>> final_q;  // joint name, q
};

RunSummary summarize(const Scene& scene, const RunResult& result);

}  // namespace unfurl
