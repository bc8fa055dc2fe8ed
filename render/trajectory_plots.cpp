#include "trajectory_plots.hpp"

#include <functional>

namespace unfurl::render {

namespace {

using Value = std::function<double(const Sample&)>;

Series series(const Trajectory& tr, const std::string& label, ImU32 color, const Value& value) {
  Series s;
  s.label = label;
  s.color = color;
  s.x.reserve(tr.samples.size());
  s.y.reserve(tr.samples.size());
  for (const Sample& sample : tr.samples) {
    s.x.push_back(sample.t);
    s.y.push_back(value(sample));
  }
  return s;
}

// Adds the curves of one run (ghost: a previous run).
void add_curves(PlotSpec& spec, PlotKind kind, const Scene& scene, const Trajectory& tr, bool ghost, int max_joints) {
  const Model& model = scene.model;
  const StateLayout& L = tr.layout;
  std::vector<Series> added;
  switch (kind) {
    case PlotKind::angles:
    case PlotKind::rates:
      for (int c = 0; c < std::min(model.nq, max_joints); ++c) {
        const std::string& joint = model.joints[model.joint_of_coordinate[c]].name;
        added.push_back(kind == PlotKind::angles
                            ? series(tr, joint, palette(c), [&, c](const Sample& s) { return s.y[L.q() + c]; })
                            : series(tr, joint, palette(c), [c](const Sample& s) { return s.dq[c]; }));
      }
      break;
    case PlotKind::residuals:
      for (std::size_t l = 0; l < scene.loops.size(); ++l) {
        const int color = static_cast<int>(l);
        added.push_back(series(tr, scene.loops[l].name + ", m", palette(color),
                               [l](const Sample& s) { return s.closure[l].distance; }));
        added.push_back(series(tr, scene.loops[l].name + ", rad", palette(color),
                               [l](const Sample& s) { return s.closure[l].angle; }));
        added.back().dashed = true;
      }
      break;
    case PlotKind::energy:
      added.push_back(series(tr, "total", palette(0), [](const Sample& s) { return s.energy.total(); }));
      if (!tr.empty() && tr.samples.front().energy.unattributed != 0) break;  // only the total is known
      added.push_back(series(tr, "kinetic", palette(1), [](const Sample& s) { return s.energy.kinetic; }));
      added.push_back(series(tr, "springs + latches", palette(2),
                             [](const Sample& s) { return s.energy.springs + s.energy.latches; }));
      break;
  }
  for (Series& s : added) {
    s.ghost = ghost;
    spec.series.push_back(std::move(s));
  }
}

}  // namespace

PlotSpec trajectory_plot(PlotKind kind, const Scene& scene, const Trajectory& trajectory, const Trajectory* ghost,
                         int max_joints) {
  PlotSpec spec;
  spec.x_label = "time, s";
  const bool truncated = scene.model.nq > max_joints;
  const std::string which = truncated ? " (first " + std::to_string(max_joints) + " joints)" : "";
  switch (kind) {
    case PlotKind::angles:
      spec.title = scene.name + ": joint angles" + which;
      spec.y_label = "q, rad";
      break;
    case PlotKind::rates:
      spec.title = scene.name + ": joint rates" + which;
      spec.y_label = "dq/dt, rad/s";
      break;
    case PlotKind::residuals:
      spec.title = scene.name + ": loop gaps (distance and angle between split body and image)";
      spec.y_label = "gap, m (solid) and rad (dashed)";
      spec.log_y = true;
      break;
    case PlotKind::energy:
      spec.title = scene.name + ": energy";
      spec.y_label = "J";
      break;
  }
  if (ghost) add_curves(spec, kind, scene, *ghost, true, max_joints);
  add_curves(spec, kind, scene, trajectory, false, max_joints);
  for (const LatchEvent& e : trajectory.events)
    if (spec.events.empty() || std::abs(spec.events.back() - e.t) > 1e-6) spec.events.push_back(e.t);
  return spec;
}

std::vector<NamedPlot> trajectory_plots(const Scene& scene, const Trajectory& trajectory, int max_joints) {
  std::vector<NamedPlot> plots;
  plots.push_back({PlotKind::angles, "angles.png", trajectory_plot(PlotKind::angles, scene, trajectory, nullptr, max_joints)});
  plots.push_back({PlotKind::rates, "rates.png", trajectory_plot(PlotKind::rates, scene, trajectory, nullptr, max_joints)});
  if (!scene.loops.empty())
    plots.push_back({PlotKind::residuals, "residuals.png", trajectory_plot(PlotKind::residuals, scene, trajectory)});
  plots.push_back({PlotKind::energy, "energy.png", trajectory_plot(PlotKind::energy, scene, trajectory)});
  return plots;
}

}  // namespace unfurl::render
