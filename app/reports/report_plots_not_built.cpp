// The reports in a build without the renderer: tables and markdown, no
// plots (the markdown lists none).
#include <cstdio>

#include "compliance_files.hpp"
#include "scaling_files.hpp"
#include "stability_files.hpp"
#include "study_plots.hpp"
#include "work_precision_files.hpp"

namespace unfurl::app {

namespace {

std::vector<std::string> no_plots() {
  static bool said = false;
  if (!said) std::fprintf(stderr, "unfurl: no plots: this unfurl was built without the renderer\n");
  said = true;
  return {};
}

}  // namespace

std::vector<std::string> write_work_precision_plots(const sim::Scene&, const studies::WorkPrecision&,
                                                    const std::string&) {
  return no_plots();
}
std::vector<std::string> write_scaling_plots(const ScalingReport&, const std::string&) { return no_plots(); }
std::vector<std::string> write_compliance_plots(const ComplianceReport&, const std::string&) { return no_plots(); }
std::vector<std::string> write_stability_plots(const StabilityReport&, const std::string&) { return no_plots(); }
std::vector<std::string> write_study_plots(const io::StudyReport&, const std::string&) { return no_plots(); }

}  // namespace unfurl::app
