// The standard plots of a run, from its trajectory: joint angles (the
// paper's figure 6), joint rates (figure 7), the loops' geometric gaps on a
// log axis (figure 8 drawn from the true gap; scenes with loops only), the
// loads (latch torques and hinge moments), the hinge forces, energy and a
// free bus's attitude
// and rate, the sensors' accelerations in g; latch events marked.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "unfurl/render/plot.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/torque_margin_result.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::render {

// torque_margin: the driven joints' motorization factors along the run,
// from margins already computed (PlotChoice::torque_margins; not among
// plot_kinds: the workbench adds it).
enum class PlotKind { angles, rates, residuals, loads, energy, bus, sensors, hinge_forces, torque_margin };

// "angles", "rates", "loop gaps", "loads", "energy", "bus", "sensors",
// "hinge forces", "torque margin".
const char* plot_kind_name(PlotKind kind);

// The plots a scene's runs have: no gap plot for a tree; the bus's attitude
// for a free-floating one; the sensors' accelerations, in g, for a scene
// whose sensors measure any.
std::vector<PlotKind> plot_kinds(const sim::Scene& scene);

struct NamedPlot {
  PlotKind kind;
  std::string file;  // angles.png, ...
  PlotSpec spec;
};

// Every plot of plot_kinds() with its file name (angles.png, rates.png,
// residuals.png, loads.png, hinge_forces.png, energy.png, bus.png,
// sensors.png). At most `max_joints` joints are
// drawn, in scene order.
std::vector<NamedPlot> trajectory_plots(const sim::Scene& scene, const sim::Trajectory& trajectory,
                                        int max_joints = 12);

// Another run drawn with the current one: the previous run (colour 0: each
// curve faint in its own colour) or a pinned run (a translucent colour of
// its own, its name in the legend).
struct ComparedRun {
  const sim::Trajectory* trajectory = nullptr;
  std::string name;
  ImU32 color = 0;
};

struct PlotChoice {
  std::vector<ComparedRun> others;
  // The coordinates whose angles and rates are drawn (and whose latches'
  // loads); empty: the first max_joints.
  std::vector<int> coordinates;
  int max_joints = 12;
  std::optional<std::pair<double, double>> time_range;  // a zoom
  // The current run's torque margins and the factor required of them (the
  // torque margin plot).
  const std::vector<sim::JointTorqueMargin>* torque_margins = nullptr;
  double required_factor = 2;
};

PlotSpec trajectory_plot(PlotKind kind, const sim::Scene& scene, const sim::Trajectory& trajectory,
                         const PlotChoice& choice = {});

// The coordinates a plot of joints draws under `choice`.
std::vector<int> chosen_coordinates(const sim::Model& model, const PlotChoice& choice);

}  // namespace unfurl::render
