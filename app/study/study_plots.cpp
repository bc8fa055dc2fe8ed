// The study's plots (needs the renderer): histograms of the deployment time
// and the peak latch torque, each headline output against its strongest
// driver, one joint's angle in every case with the nominal case on top, and
// for a study of failures each failure case's outcomes against the nominal.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "report_plots.hpp"
#include "graphics_functions.hpp"

namespace unfurl::app {

namespace {

std::vector<double> deployed_values(const io::StudyReport& report, const std::string& output) {
  std::vector<double> x;
  for (const studies::CaseResult& r : report.results) {
    const double v = studies::output_value(report.columns, r, output);
    if (r.status == studies::CaseStatus::deployed && r.failure.empty() && std::isfinite(v)) x.push_back(v);
  }
  return x;
}

// Counts per bin drawn as a staircase (the plot draws lines, not bars).
render::PlotSpec histogram(const io::StudyReport& report, const std::string& output, const std::string& x_label) {
  const std::vector<double> x = deployed_values(report, output);
  render::PlotSpec spec;
  spec.title = "histogram of " + output + " over " + std::to_string(x.size()) + " deployed cases";
  spec.x_label = x_label;
  spec.y_label = "cases per bin";
  const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
  const double lo = *lo_it, hi = *hi_it > *lo_it ? *hi_it : *lo_it + 1e-9 * (1 + std::abs(*lo_it));
  const int bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(x.size())))), 5, 40);
  std::vector<double> count(bins, 0);
  for (double v : x) count[std::min(bins - 1, static_cast<int>((v - lo) / (hi - lo) * bins))] += 1;
  render::Series s;
  s.label = output;
  s.color = render::palette(0);
  const double w = (hi - lo) / bins;
  s.x.push_back(lo), s.y.push_back(0);
  for (int b = 0; b < bins; ++b) {
    s.x.push_back(lo + b * w), s.y.push_back(count[b]);
    s.x.push_back(lo + (b + 1) * w), s.y.push_back(count[b]);
  }
  s.x.push_back(hi), s.y.push_back(0);
  spec.series.push_back(std::move(s));
  return spec;
}

render::PlotSpec scatter(const io::StudyReport& report, const studies::Driver& d) {
  render::PlotSpec spec;
  char rho[32];
  std::snprintf(rho, sizeof rho, "%.3f", d.rho);
  spec.title = d.output + " against " + d.input + " (Spearman rho " + rho + ")" +
               (d.together.empty() ? "" : ", with " + std::to_string(d.together.size()) + " inputs that moved with it");
  spec.x_label = d.input;
  spec.y_label = d.output;
  const auto input = static_cast<std::size_t>(
      std::find(report.columns.inputs.begin(), report.columns.inputs.end(), d.input) - report.columns.inputs.begin());
  render::Series cases, nominal;
  cases.label = "deployed cases";
  cases.color = render::palette(0);
  cases.markers = true;
  cases.lines = false;
  nominal.label = "nominal";
  nominal.color = render::palette(1);
  nominal.markers = true;
  nominal.lines = false;
  for (const studies::CaseResult& r : report.results) {
    const double y = studies::output_value(report.columns, r, d.output);
    if (r.status != studies::CaseStatus::deployed || !r.failure.empty() || !std::isfinite(y)) continue;
    render::Series& s = r.id == "nominal" ? nominal : cases;
    s.x.push_back(r.inputs[input]);
    s.y.push_back(y);
  }
  spec.series = {cases, nominal};
  return spec;
}

render::PlotSpec overlay(const io::StudyReport& report) {
  render::PlotSpec spec;
  spec.title = "angle of " + report.study.overlay_joint + " in every case";
  spec.x_label = "t, s";
  spec.y_label = "q." + report.study.overlay_joint + ", rad";
  spec.ghost_label = "other cases (red: not deployed)";
  for (const studies::CaseResult& r : report.results) {
    if (r.angle_t.empty()) continue;
    render::Series s;
    s.x = r.angle_t;
    s.y = r.angle;
    if (r.id == "nominal") {
      s.label = "nominal";
      s.color = render::palette(1);
    } else {
      s.label = r.status == studies::CaseStatus::deployed ? "deployed case" : "not deployed or failed";
      s.color = r.status == studies::CaseStatus::deployed ? render::palette(0) : render::palette(3);
      s.ghost = true;
    }
    spec.series.push_back(std::move(s));
  }
  // The nominal case is drawn last, over the others.
  std::stable_partition(spec.series.begin(), spec.series.end(), [](const render::Series& s) { return s.ghost; });
  return spec;
}

// One outcome of every failure case, a row each, against the nominal
// case's (the dashed line). A case without the outcome (a deployment time
// where it did not deploy) has no dot, and its row says why.
struct Outcome {
  std::string output, name, axis;  // the column, what the title calls it, the axis' label less the unit
};

render::PlotSpec failure_outcomes(const io::StudyReport& report, const Outcome& outcome,
                                  const studies::CaseResult& nominal) {
  const std::string& output = outcome.output;
  const std::string unit = studies::output_unit(output);
  render::PlotSpec spec;
  spec.title = outcome.name + " of each failure case against the nominal";
  spec.x_label = unit.empty() ? outcome.axis : outcome.axis + ", " + unit;
  render::Series deployed, not_deployed;
  deployed.label = "deployed";
  not_deployed.label = "not deployed or failed";
  deployed.color = render::palette(0);
  not_deployed.color = render::palette(3);
  for (render::Series* s : {&deployed, &not_deployed}) s->markers = true, s->lines = false;
  for (const studies::CaseResult& r : report.results) {
    if (r.failure.empty()) continue;
    const double row = static_cast<double>(spec.y_categories.size());
    spec.y_categories.push_back(r.id + (r.status == studies::CaseStatus::deployed ? "" : " (" + std::string(studies::case_status_name(r.status)) + ")"));
    const double v = studies::output_value(report.columns, r, output);
    if (!std::isfinite(v)) continue;
    render::Series& s = r.status == studies::CaseStatus::deployed ? deployed : not_deployed;
    s.x.push_back(v);
    s.y.push_back(row);
  }
  const double at = studies::output_value(report.columns, nominal, output);
  if (std::isfinite(at)) {
    spec.events.push_back(at);
    char text[64];
    std::snprintf(text, sizeof text, "nominal (%.4g)", at);
    spec.event_label = text;
  }
  // Every dot and the nominal inside the axes, with room at both ends.
  std::vector<double> x = spec.events;
  for (const render::Series* s : {&deployed, &not_deployed}) x.insert(x.end(), s->x.begin(), s->x.end());
  if (!x.empty()) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const double pad = *hi > *lo ? 0.06 * (*hi - *lo) : 0.1 * std::max(std::abs(*lo), 1e-12);
    spec.x_range = std::make_pair(*lo - pad, *hi + pad);
  }
  for (render::Series* s : {&deployed, &not_deployed})
    if (!s->x.empty()) spec.series.push_back(std::move(*s));
  return spec;
}

}  // namespace

std::vector<std::string> study_plot_files(const io::StudyReport& report, const std::string& dir) {
  std::vector<std::pair<render::PlotSpec, std::string>> plots;
  if (deployed_values(report, "deployment_time").size() >= 2)
    plots.emplace_back(histogram(report, "deployment_time", "deployment time (last latch engaged), s"),
                       "hist_deployment_time.png");
  if (deployed_values(report, "peak_latch_torque").size() >= 2)
    plots.emplace_back(histogram(report, "peak_latch_torque", "peak latch torque over all latches, N m"),
                       "hist_peak_latch_torque.png");
  for (const studies::Driver& d : report.statistics.drivers)
    plots.emplace_back(scatter(report, d), "scatter_" + d.output + ".png");
  plots.emplace_back(overlay(report), "overlay_angles.png");
  const auto nominal = std::find_if(report.results.begin(), report.results.end(),
                                    [](const studies::CaseResult& r) { return r.id == "nominal"; });
  const bool failures = std::any_of(report.results.begin(), report.results.end(),
                                    [](const studies::CaseResult& r) { return !r.failure.empty(); });
  if (failures && nominal != report.results.end())
    for (const Outcome& o : std::vector<Outcome>{
             {"deployment_time", "deployment time", "deployment time (last latch engaged)"},
             {"peak_latch_torque", "peak latch torque", "peak latch torque over all latches"},
             {"peak_hinge_force", "peak hinge force", "peak hinge force over all hinges"},
             {"torque_margin", "torque margin", "torque margin (smallest motorization factor - 1)"},
             {"min_clearance", "clearance", "closest approach of unjointed bodies (0: touching)"}})
      plots.emplace_back(failure_outcomes(report, o, *nominal), "failures_" + o.output + ".png");
  return write_plot_pngs(plots, dir);
}

}  // namespace unfurl::app
