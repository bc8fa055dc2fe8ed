// The scaling report's plots (needs the renderer).
#include <cstdio>
#include <map>

#include "report_plots.hpp"
#include "graphics_functions.hpp"

namespace unfurl::app {

namespace {

render::PlotSpec rhs_plot(const ScalingReport& report) {
  render::PlotSpec spec;
  spec.title = "right-hand side: time per body";
  spec.y_label = "ns per body per call (median)";
  spec.x_label = "bodies";
  spec.log_x = spec.log_y = true;
  std::map<std::string, render::Series> curves;
  for (const studies::RhsTiming& t : report.rhs) {
    render::Series& s = curves[studies::family_label(t.scene)];
    s.x.push_back(t.bodies);
    s.y.push_back(t.ns_per_body);
  }
  spec.series = marked_series(std::move(curves));
  return spec;
}

render::PlotSpec run_plot(const ScalingReport& report) {
  render::PlotSpec spec;
  char title[128];
  std::snprintf(title, sizeof title, "whole runs of %g s: wall time against size", report.run_t_end);
  spec.title = title;
  spec.y_label = "wall time, s (finished runs; rtol 1e-8)";
  spec.x_label = "bodies";
  spec.log_x = spec.log_y = true;
  std::map<std::string, render::Series> curves;
  for (const studies::RunTiming& t : report.runs) {
    if (t.status != sim::RunStatus::finished) continue;
    render::Series& s = curves[t.scene.family + ", " + t.method];
    s.x.push_back(t.bodies);
    s.y.push_back(t.wall_time_s);
  }
  spec.series = marked_series(std::move(curves));
  return spec;
}

}  // namespace

std::vector<std::string> scaling_plot_files(const ScalingReport& report, const std::string& dir) {
  std::vector<std::pair<render::PlotSpec, std::string>> plots;
  if (!report.rhs.empty()) plots.emplace_back(rhs_plot(report), "rhs_per_body.png");
  if (!report.runs.empty()) plots.emplace_back(run_plot(report), "run_wall_time.png");
  return write_plot_pngs(plots, dir);
}

}  // namespace unfurl::app
