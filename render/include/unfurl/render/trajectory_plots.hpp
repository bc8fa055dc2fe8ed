// The standard plots of a run, from its trajectory: joint angles (the
// paper's figure 6), joint rates (figure 7), the loops' geometric gaps on a
// log axis (figure 8 drawn from the true gap; scenes with loops only), the
// loads (latch torques and hinge moments) and energy; latch events marked.
#pragma once

#include <string>
#include <vector>

#include "unfurl/render/plot.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::render {

enum class PlotKind { angles, rates, residuals, loads, energy };

// "angles", "rates", "loop gaps", "loads", "energy".
const char* plot_kind_name(PlotKind kind);

// The plots a scene's runs have: no gap plot for a tree.
std::vector<PlotKind> plot_kinds(const Scene& scene);

struct NamedPlot {
  PlotKind kind;
  std::string file;  // angles.png, ...
  PlotSpec spec;
};

// Every plot of plot_kinds() with its file name (angles.png, rates.png,
// residuals.png, loads.png, energy.png). At most `max_joints` joints are
// drawn, in scene order.
std::vector<NamedPlot> trajectory_plots(const Scene& scene, const Trajectory& trajectory, int max_joints = 12);

// One plot; `ghost` (may be null) adds a previous run's curves, faint.
PlotSpec trajectory_plot(PlotKind kind, const Scene& scene, const Trajectory& trajectory,
                         const Trajectory* ghost = nullptr, int max_joints = 12);

}  // namespace unfurl::render
