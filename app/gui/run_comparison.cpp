#include "run_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace unfurl::app {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

double figure(const std::vector<RunFigure>& figures, const std::string& name) {
  const auto it = std::find_if(figures.begin(), figures.end(), [&](const RunFigure& f) { return f.name == name; });
  return it == figures.end() ? kNone : it->value;
}

}  // namespace

std::vector<RunFigure> run_figures(const sim::RunSummary& s) {
  std::vector<RunFigure> figures;
  double last_latch = s.latch_times.empty() ? kNone : 0;
  for (const auto& [joint, t] : s.latch_times) last_latch = std::max(last_latch, t);
  // Deployed: every latch engaged; the deployment ends at the last of them.
  figures.push_back({"deployment time, s", s.unlatched.empty() ? last_latch : kNone});
  double peak = s.peak_latch_torque.empty() ? kNone : 0;
  for (const auto& p : s.peak_latch_torque) peak = std::max(peak, p.peak.value);
  figures.push_back({"peak latch torque, N m", peak});
  // Hinge loads over the steps where rigid mechanics determines them.
  const auto largest = [](const std::vector<sim::RunSummary::NamedPeak>& peaks) {
    double m = kNone;
    for (const auto& p : peaks)
      if (!std::isnan(p.peak.t) && !(p.peak.value <= m)) m = p.peak.value;
    return m;
  };
  figures.push_back({"peak hinge force, N", largest(s.peak_hinge_force)});
  figures.push_back({"peak hinge moment, N m", largest(s.peak_hinge_moment)});
  figures.push_back({"torque margin", s.torque_margins.empty() ? kNone : s.worst_motorization_factor() - 1});
  // The sensors' and the bushings' peaks by name: "peak_acceleration.tip, m/s^2".
  for (const auto& peaks : {s.sensor_peaks, s.element_peaks})
    for (const auto& p : peaks)
      figures.push_back({p.quantity + "." + p.name + (p.unit.empty() ? "" : ", " + p.unit), p.peak.value});
  const sim::PairClearance* closest = s.clearance ? s.clearance->closest() : nullptr;
  figures.push_back({"clearance, m", closest ? closest->distance : kNone});
  figures.push_back({"spans of contact", closest ? static_cast<double>(s.clearance->contacts.size()) : kNone});
  figures.push_back({"final energy, J", s.energy_final});
  figures.push_back({"dissipated, J", s.energy_dissipated});
  if (s.energy_driven) figures.push_back({"put in by drivers, J", *s.energy_driven});
  figures.push_back({"largest gap, m", s.max_closure_gap});
  figures.push_back({"largest gap, rad", s.max_closure_angle});
  for (const auto& [joint, t] : s.latch_times) figures.push_back({"latch " + joint + ", s", t});
  for (const std::string& joint : s.unlatched) figures.push_back({"latch " + joint + ", s", kNone});
  return figures;
}

SceneShape scene_shape(const sim::Scene& scene) {
  return {scene.name, scene.model.size(), scene.model.nq, static_cast<int>(scene.loops.size())};
}

ImU32 pinned_color(int k) {
  static const ImU32 colors[] = {IM_COL32(240, 240, 240, 200), IM_COL32(255, 214, 60, 200),
                                 IM_COL32(90, 230, 230, 200), IM_COL32(255, 120, 230, 200),
                                 IM_COL32(150, 255, 120, 200), IM_COL32(255, 160, 110, 200)};
  return colors[k % 6];
}

std::vector<ComparisonRow> compare_runs(const sim::RunSummary& current, const std::vector<PinnedRun>& pinned) {
  std::vector<std::vector<RunFigure>> figures;
  for (const PinnedRun& p : pinned) figures.push_back(p.summary ? run_figures(*p.summary) : std::vector<RunFigure>{});
  std::vector<ComparisonRow> rows;
  auto add_row = [&](const std::string& name, double value) {
    if (std::any_of(rows.begin(), rows.end(), [&](const ComparisonRow& r) { return r.name == name; })) return;
    ComparisonRow row{name, value, {}};
    for (const auto& f : figures) row.pinned.push_back(figure(f, name));
    rows.push_back(std::move(row));
  };
  for (const RunFigure& f : run_figures(current)) add_row(f.name, f.value);
  for (const auto& list : figures)
    for (const RunFigure& f : list) add_row(f.name, kNone);
  return rows;
}

}  // namespace unfurl::app
