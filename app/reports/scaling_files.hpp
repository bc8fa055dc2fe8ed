// The scaling report: SCALING.md, rhs_scaling.csv, run_scaling.csv and its
// plots (right-hand side time per body, whole-run wall time against size).
#pragma once

#include <string>
#include <vector>

#include "unfurl/studies/scaling.hpp"

namespace unfurl::app {

struct ScalingReport {
  std::vector<studies::RhsTiming> rhs;
  std::vector<studies::RunTiming> runs;
  double run_t_end = 1, budget_s = 0;
  std::string command;
};

std::vector<std::string> write_scaling_plots(const ScalingReport& report, const std::string& dir);
void write_scaling_csv(const ScalingReport& report, const std::string& dir);
void write_scaling_markdown(const ScalingReport& report, const std::vector<std::string>& pictures,
                            const std::string& path);

}  // namespace unfurl::app
