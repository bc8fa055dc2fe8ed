// The work-precision report's files: work_precision.csv (every run),
// WORK_PRECISION.md (reference, table, cheapest integrator per accuracy)
// and the log-log plots. Each file complete or absent.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/studies/work_precision.hpp"

namespace unfurl::app {

void write_work_precision_csv(const studies::WorkPrecision& report, const std::string& path);
void write_work_precision_markdown(const sim::Scene& scene, const studies::WorkPrecision& report,
                                   const std::vector<std::string>& pictures, const std::string& command,
                                   const std::string& path);
// The PNGs (angle error; with latches, latch-time and final-state error);
// returns their file names inside dir.
std::vector<std::string> write_work_precision_plots(const sim::Scene& scene, const studies::WorkPrecision& report,
                                                    const std::string& dir);

}  // namespace unfurl::app
