// The stability report's plots (needs the renderer).
#include <cmath>
#include <cstdlib>
#include <map>

#include "report_plots.hpp"
#include "graphics_functions.hpp"

namespace unfurl::app {

namespace {

render::Series series(const std::string& label, int color, std::vector<double> x, std::vector<double> y) {
  render::Series s;
  s.label = label;
  s.color = render::palette(color);
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

render::PlotSpec gains_residual_plot(const studies::GainComparison& g) {
  render::PlotSpec spec;
  spec.title = "pantograph: loop gap, paper's diagonal gains (16) against full-matrix gains";
  spec.y_label = "largest geometric gap, m and rad";
  spec.x_label = "time, s";
  spec.log_y = true;
  spec.series.push_back(series("paper (16), diagonal of W(0)", 3, g.t_paper, g.residual_paper));
  spec.series.push_back(series("full, from the current W", 0, g.t_full, g.residual_full));
  for (auto& s : spec.series)
    for (double& y : s.y) y = std::max(y, 1e-17);
  return spec;
}

render::PlotSpec gains_eigen_plot(const studies::GainComparison& g) {
  render::PlotSpec spec;
  spec.title = "pantograph: smallest eigenvalue a of W diag(W)^-1 along the run";
  spec.y_label = "a (the paper's tuning is stable only above the Routh bound)";
  spec.x_label = "time, s";
  spec.log_y = true;
  spec.series.push_back(series("smallest a", 0, g.t_eigen, g.smallest_eigen));
  for (double& y : spec.series[0].y) y = std::max(y, 1e-12);
  if (!g.t_eigen.empty())
    spec.series.push_back(series("Routh bound p0/((p0+2p1)(1+2p0p1))", 3, {g.t_eigen.front(), g.t_eigen.back()},
                                 {g.routh_bound, g.routh_bound}));
  return spec;
}

render::PlotSpec long_run_plot(const studies::StabilityResult& r) {
  render::PlotSpec spec;
  spec.title = r.spec.label + ": energy drift and loop closure";
  spec.y_label = "|E - E0| / |E0|, closure m and rad";
  spec.x_label = "time, s";
  spec.log_y = true;
  std::vector<double> t, drift, closure_m, closure_rad;
  const double E0 = r.trajectory.samples.front().energy.total();
  for (const sim::Sample& s : r.trajectory.samples) {
    t.push_back(s.t);
    drift.push_back(std::max(std::abs(s.energy.total() - E0) / std::abs(E0), 1e-17));
    double m = 0, rad = 0;
    for (const sim::ClosureError& c : s.closure) m = std::max(m, c.distance), rad = std::max(rad, c.angle);
    closure_m.push_back(std::max(m, 1e-17));
    closure_rad.push_back(std::max(rad, 1e-17));
  }
  spec.series.push_back(series("energy drift", 0, t, drift));
  spec.series.push_back(series("closure, m", 1, t, closure_m));
  spec.series.push_back(series("closure, rad", 2, t, closure_rad));
  return spec;
}

// Wall time against a case parameter, one curve per key (integrator, kind).
render::PlotSpec wall_time_plot(const std::string& title, const std::string& x_label,
                                std::map<std::string, render::Series> curves) {
  render::PlotSpec spec;
  spec.title = title;
  spec.y_label = "wall time, s (finished runs)";
  spec.x_label = x_label;
  spec.log_x = spec.log_y = true;
  spec.series = marked_series(std::move(curves));
  return spec;
}

double first_number(const std::string& text, const std::string& after) {
  const auto at = text.find(after);
  return at == std::string::npos ? NAN : std::atof(text.c_str() + at + after.size());
}

}  // namespace

std::vector<std::string> stability_plot_files(const StabilityReport& report, const std::string& dir) {
  std::vector<std::pair<render::PlotSpec, std::string>> plots;
  if (report.has_gains) {
    plots.emplace_back(gains_residual_plot(report.gains), "gains_residuals.png");
    plots.emplace_back(gains_eigen_plot(report.gains), "gains_eigenvalue.png");
  }
  std::map<std::string, render::Series> stiffness, arrays;
  for (const studies::StabilityResult& r : report.results) {
    if (r.spec.conservative && !r.trajectory.empty() && r.spec.label.find("1e4") != std::string::npos)
      plots.emplace_back(long_run_plot(r), "long_run.png");
    if (r.status != sim::RunStatus::finished) continue;
    if (r.spec.group == "latch stiffness") {
      auto& c = stiffness[r.spec.label.substr(r.spec.label.find(", ") + 2)];
      c.x.push_back(first_number(r.spec.label, "k_L = "));
      c.y.push_back(r.wall_time_s);
    } else if (r.spec.group == "large array") {
      auto& c = arrays[r.spec.scene.substr(0, r.spec.scene.find(':')) + ", 1 s"];
      c.x.push_back(r.bodies);
      c.y.push_back(r.wall_time_s);
    }
  }
  if (!stiffness.empty())
    plots.emplace_back(wall_time_plot("pantograph: wall time against latch stiffness", "k_L, N m/rad", stiffness),
                       "latch_stiffness.png");
  if (!arrays.empty())
    plots.emplace_back(wall_time_plot("large arrays: wall time of the first second", "bodies", arrays),
                       "large_arrays.png");
  return write_plot_pngs(plots, dir);
}

}  // namespace unfurl::app
