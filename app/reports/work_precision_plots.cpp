// The work-precision report's plots (needs the renderer).
#include "report_plots.hpp"
#include "graphics_functions.hpp"

namespace unfurl::app {

std::vector<std::string> work_precision_plot_files(const sim::Scene& scene, const studies::WorkPrecision& report,
                                                    const std::string& dir) {
  std::vector<std::pair<PrecisionMeasure, std::string>> plots{{PrecisionMeasure::angle_error, "work_precision.png"}};
  if (!scene.latches().empty()) {
    plots.emplace_back(PrecisionMeasure::latch_time_error, "work_precision_latch.png");
    plots.emplace_back(PrecisionMeasure::final_error, "work_precision_final.png");
  }
  std::vector<std::pair<render::PlotSpec, std::string>> specs;
  for (const auto& [measure, name] : plots) specs.emplace_back(work_precision_plot(report, measure), name);
  return write_plot_pngs(specs, dir);
}

}  // namespace unfurl::app
