// The standard plots of a run, from its trajectory: joint angles (the
// paper's figure 6), joint rates (figure 7), loop residuals |eps pi| on a
// log axis (figure 8; scenes with loops only) and energy; latch events
// marked.
#pragma once

#include <string>
#include <vector>

#include "plot.hpp"
#include "scene.hpp"
#include "trajectory.hpp"

namespace unfurl::render {

enum class PlotKind { angles, rates, residuals, energy };

struct NamedPlot {
  PlotKind kind;
  std::string file;  // angles.png, ...
  PlotSpec spec;
};

// The plots this scene has (no residual plot for a tree). At most
// `max_joints` joints are drawn, in scene order.
std::vector<NamedPlot> trajectory_plots(const Scene& scene, const Trajectory& trajectory, int max_joints = 12);

// One plot; `ghost` (may be null) adds a previous run's curves, faint.
PlotSpec trajectory_plot(PlotKind kind, const Scene& scene, const Trajectory& trajectory,
                         const Trajectory* ghost = nullptr, int max_joints = 12);

}  // namespace unfurl::render
