#include "unfurl/render/trajectory_plots.hpp"

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
    case PlotKind::loads: {
      // Latch torques (solid) and the hinge moments' magnitudes (dashed) of
      // the latched joints, or of the first joints of a scene without latches.
      if (tr.empty() || tr.samples.front().loads.joints.empty()) break;
      std::vector<int> joints;
      for (const Latch& latch : scene.latches) joints.push_back(latch.joint);
      for (int j = 0; joints.empty() && j < std::min(model.size(), max_joints); ++j) joints.push_back(j);
      if (static_cast<int>(joints.size()) > max_joints / 2) joints.resize(std::max(1, max_joints / 2));
      for (std::size_t k = 0; k < joints.size(); ++k) {
        const int j = joints[k];
        const std::string& name = model.joints[j].name;
        const ImU32 color = palette(static_cast<int>(k));
        if (!scene.latches.empty())
          added.push_back(series(tr, "latch " + name, color, [j](const Sample& s) { return s.loads.joints[j].latch; }));
        added.push_back(series(tr, "|hinge moment| " + name, color, [j](const Sample& s) {
          return s.loads.joints[j].reaction.tail<3>().norm();
        }));
        added.back().dashed = !scene.latches.empty();
      }
      break;
    }
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
    case PlotKind::loads:
      spec.title = scene.name + (scene.latches.empty() ? ": hinge moments" : ": latch torques and hinge moments");
      spec.y_label = "N m (hinge moments about the hinge point)";
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

const char* plot_kind_name(PlotKind kind) {
  switch (kind) {
    case PlotKind::angles: return "angles";
    case PlotKind::rates: return "rates";
    case PlotKind::residuals: return "loop gaps";
    case PlotKind::loads: return "loads";
    case PlotKind::energy: return "energy";
  }
  return "?";
}

std::vector<PlotKind> plot_kinds(const Scene& scene) {
  std::vector<PlotKind> kinds{PlotKind::angles, PlotKind::rates};
  if (!scene.loops.empty()) kinds.push_back(PlotKind::residuals);
  kinds.push_back(PlotKind::loads);
  kinds.push_back(PlotKind::energy);
  return kinds;
}

std::vector<NamedPlot> trajectory_plots(const Scene& scene, const Trajectory& trajectory, int max_joints) {
  static const char* files[] = {"angles.png", "rates.png", "residuals.png", "loads.png", "energy.png"};
  std::vector<NamedPlot> plots;
  for (PlotKind kind : plot_kinds(scene)) {
    if (kind == PlotKind::loads && (trajectory.empty() || trajectory.samples.front().loads.joints.empty())) continue;
    plots.push_back({kind, files[static_cast<int>(kind)], trajectory_plot(kind, scene, trajectory, nullptr, max_joints)});
  }
  return plots;
}

}  // namespace unfurl::render
