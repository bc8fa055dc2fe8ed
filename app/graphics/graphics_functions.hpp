// What the graphics module (libunfurl_graphics.so: the renderer, the
// workbench and every plot) gives the command line, which loads it only
// when a command draws (render, gui, and report and study for their plots):
// `simulate`, `generate`, `modes` and `export` load no GL library. Both
// sides are built from this tree together, so the table passes C++ types;
// exceptions thrown inside reach the command's handlers because libstdc++
// matches their types by name.
#pragma once

#include <string>
#include <vector>

#include "compliance_files.hpp"
#include "scaling_files.hpp"
#include "stability_files.hpp"
#include "unfurl/io/study_files.hpp"
#include "work_precision_files.hpp"

namespace unfurl::app {

struct GraphicsFunctions {
  int (*render)(const std::vector<std::string>& args);
  int (*gui)(const std::vector<std::string>& args);  // null where the workbench was not built
  std::vector<std::string> (*work_precision_plots)(const sim::Scene& scene, const studies::WorkPrecision& report,
                                                   const std::string& dir);
  std::vector<std::string> (*scaling_plots)(const ScalingReport& report, const std::string& dir);
  std::vector<std::string> (*compliance_plots)(const ComplianceReport& report, const std::string& dir);
  std::vector<std::string> (*stability_plots)(const StabilityReport& report, const std::string& dir);
  std::vector<std::string> (*study_plots)(const io::StudyReport& report, const std::string& dir);
};

// The module's one exported symbol.
inline constexpr const char* kGraphicsEntry = "unfurl_graphics_functions";

// The graphics side's own names for what the table holds.
int render_command(const std::vector<std::string>& args);
int gui_command(const std::vector<std::string>& args);
std::vector<std::string> work_precision_plot_files(const sim::Scene& scene, const studies::WorkPrecision& report,
                                                   const std::string& dir);
std::vector<std::string> scaling_plot_files(const ScalingReport& report, const std::string& dir);
std::vector<std::string> compliance_plot_files(const ComplianceReport& report, const std::string& dir);
std::vector<std::string> stability_plot_files(const StabilityReport& report, const std::string& dir);
std::vector<std::string> study_plot_files(const io::StudyReport& report, const std::string& dir);

}  // namespace unfurl::app

extern "C" const unfurl::app::GraphicsFunctions* unfurl_graphics_functions();
