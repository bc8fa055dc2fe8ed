// The stability report's files: STABILITY.md (every case, the largest
// latch stiffness per integrator, the regulator tunings, the long run) and
// its plots. Each file complete or absent.
#pragma once

#include <string>
#include <vector>

#include "unfurl/studies/gain_study.hpp"
#include "unfurl/studies/stability_results.hpp"
#include "unfurl/studies/stability_verdicts.hpp"

namespace unfurl::app {

struct StabilityReport {
  std::vector<studies::StabilityResult> results;
  studies::GainComparison gains;
  bool has_gains = false;
  double budget_s = 0;
  std::string command;
};

// Writes the PNGs into dir and returns their names.
std::vector<std::string> write_stability_plots(const StabilityReport& report, const std::string& dir);
void write_stability_markdown(const StabilityReport& report, const std::vector<std::string>& pictures,
                              const std::string& path);
void write_stability_csv(const StabilityReport& report, const std::string& path);

}  // namespace unfurl::app
