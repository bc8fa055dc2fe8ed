// The compliance report's plot (needs the renderer).
#include <map>

#include "graphics_functions.hpp"
#include "report_plots.hpp"

namespace unfurl::app {

namespace {

render::PlotSpec pin_stiffness_plot(const ComplianceReport& report) {
  render::PlotSpec spec;
  spec.title = "compliant pantograph: peak hinge force against pin stiffness";
  spec.x_label = "pin stiffness, N/m (all three axes of every cross-link)";
  spec.y_label = "peak hinge force, N";
  spec.log_x = spec.log_y = true;
  const auto deployments = studies::pin_stiffness_deployments();
  std::map<std::string, render::Series> curves;
  double k_min = 0, k_max = 0;
  for (const auto& c : report.compliant) {
    if (c.loads.status != sim::RunStatus::finished) continue;
    render::Series& s = curves[deployments[c.deployment].label];
    s.x.push_back(c.stiffness);
    s.y.push_back(c.loads.peak_hinge_force);
    k_min = k_min == 0 ? c.stiffness : std::min(k_min, c.stiffness);
    k_max = std::max(k_max, c.stiffness);
  }
  spec.series = marked_series(std::move(curves));
  for (const auto& c : report.rigid) {
    if (c.loads.status != sim::RunStatus::finished || c.deployment != 0 || k_max == 0) continue;
    render::Series rigid;
    rigid.label = "rigid pantograph, nominal";
    rigid.x = {k_min, k_max};
    rigid.y = {c.loads.peak_hinge_force, c.loads.peak_hinge_force};
    rigid.color = IM_COL32(90, 90, 90, 255);
    rigid.dashed = true;
    spec.series.push_back(rigid);
  }
  return spec;
}

// The studies' empirical distributions: the fraction of cases at or below
// each peak hinge force.
render::PlotSpec monte_carlo_plot(const ComplianceReport& report) {
  render::PlotSpec spec;
  spec.title = "Monte Carlo: peak hinge force, rigid and compliant pantograph";
  spec.x_label = "peak hinge force, N";
  spec.y_label = "fraction of deployed cases at or below";
  spec.log_x = true;
  int k = 0;
  for (const MonteCarloHingeForces& m : report.monte_carlo) {
    render::Series s;
    s.label = m.label;
    s.color = render::palette(k++);
    const double n = static_cast<double>(m.peak_hinge_force.size());
    for (std::size_t i = 0; i < m.peak_hinge_force.size(); ++i) {
      s.x.push_back(m.peak_hinge_force[i]), s.y.push_back(i / n);
      s.x.push_back(m.peak_hinge_force[i]), s.y.push_back((i + 1) / n);
    }
    spec.series.push_back(std::move(s));
  }
  return spec;
}

}  // namespace

std::vector<std::string> compliance_plot_files(const ComplianceReport& report, const std::string& dir) {
  std::vector<std::pair<render::PlotSpec, std::string>> plots{{pin_stiffness_plot(report), "pin_stiffness.png"}};
  if (!report.monte_carlo.empty()) plots.emplace_back(monte_carlo_plot(report), "monte_carlo_hinge_force.png");
  return write_plot_pngs(plots, dir);
}

}  // namespace unfurl::app
