#include "unfurl/render/trajectory_plots.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace unfurl::render {

namespace {

using Value = std::function<double(const sim::Sample&)>;

Series series(const sim::Trajectory& tr, const std::string& label, ImU32 color, const Value& value) {
  Series s;
  s.label = label;
  s.color = color;
  s.x.reserve(tr.samples.size());
  s.y.reserve(tr.samples.size());
  for (const sim::Sample& sample : tr.samples) {
    s.x.push_back(sample.t);
    s.y.push_back(value(sample));
  }
  return s;
}

}  // namespace

std::vector<int> chosen_coordinates(const sim::Model& model, const PlotChoice& choice) {
  std::vector<int> coordinates;
  // The one-coordinate joints' angles (a free bus has a plot of its own).
  const int n1 = model.scalar_coordinates;
  for (int c : choice.coordinates)
    if (c >= 0 && c < n1) coordinates.push_back(c);
  if (choice.coordinates.empty())
    for (int c = 0; c < std::min(n1, choice.max_joints); ++c) coordinates.push_back(c);
  return coordinates;
}

namespace {

// Adds the curves of one run (`other`: a run compared with the current one).
void add_curves(PlotSpec& spec, PlotKind kind, const sim::Scene& scene, const sim::Trajectory& tr,
                const ComparedRun* other, const PlotChoice& choice) {
  const sim::Model& model = scene.model;
  const sim::StateLayout& L = tr.layout;
  const std::vector<int> coordinates = chosen_coordinates(model, choice);
  std::vector<Series> added;
  switch (kind) {
    case PlotKind::angles:
    case PlotKind::rates:
      for (int c : coordinates) {
        const std::string& joint = model.joints[model.joint_of_position[c]].name;
        added.push_back(kind == PlotKind::angles
                            ? series(tr, joint, palette(c), [&, c](const sim::Sample& s) { return s.y[L.q() + c]; })
                            : series(tr, joint, palette(c), [c](const sim::Sample& s) { return s.q_dot[c]; }));
      }
      break;
    case PlotKind::residuals:
      for (std::size_t l = 0; l < scene.loops.size(); ++l) {
        const int color = static_cast<int>(l);
        added.push_back(series(tr, scene.loops[l].name + ", m", palette(color),
                               [l](const sim::Sample& s) { return s.closure[l].distance; }));
        added.push_back(series(tr, scene.loops[l].name + ", rad", palette(color),
                               [l](const sim::Sample& s) { return s.closure[l].angle; }));
        added.back().dashed = true;
      }
      break;
    case PlotKind::torque_margin:  // the current run's, from its margins (add_margins)
      break;
    case PlotKind::hinge_forces:
    case PlotKind::loads: {
      // Latch and drive torques (solid) and the hinge moments' magnitudes (dashed), or
      // the hinge forces' magnitudes, of the latched joints, or of the
      // first joints of a scene without latches.
      if (tr.empty() || tr.samples.front().loads.reaction.empty()) break;
      const int max_joints = choice.max_joints;
      const auto chosen = [&](int j) {
        const int c = model.first_position[j].value;
        return choice.coordinates.empty() || std::find(coordinates.begin(), coordinates.end(), c) != coordinates.end();
      };
      const std::vector<const sim::Latch*> latches = scene.latches();
      std::vector<int> joints;
      for (const sim::Latch* latch : latches)
        if (chosen(latch->joint)) joints.push_back(latch->joint);
      for (int j = 0; latches.empty() && j < model.size() && static_cast<int>(joints.size()) < max_joints; ++j)
        if (chosen(j)) joints.push_back(j);
      // Two curves a joint in the loads plot, one in the forces'.
      const int most = kind == PlotKind::loads ? std::max(1, max_joints / 2) : max_joints;
      if (static_cast<int>(joints.size()) > most) joints.resize(most);
      for (std::size_t k = 0; k < joints.size(); ++k) {
        const int j = joints[k];
        const std::string& name = model.joints[j].name;
        const ImU32 color = palette(static_cast<int>(k));
        if (kind == PlotKind::hinge_forces) {
          added.push_back(series(tr, "|hinge force| " + name, color,
                                 [j](const sim::Sample& s) { return s.loads.reaction[j].head<3>().norm(); }));
          continue;
        }
        const int latch = sim::find_load_column(tr.load_columns, "latch_torque." + name);
        if (latch >= 0)
          added.push_back(
              series(tr, "latch " + name, color, [latch](const sim::Sample& s) { return s.loads.element[latch]; }));
        const int drive = sim::find_load_column(tr.load_columns, "drive_torque." + name);
        if (drive >= 0)
          added.push_back(
              series(tr, "drive " + name, color, [drive](const sim::Sample& s) { return s.loads.element[drive]; }));
        added.push_back(series(tr, "|hinge moment| " + name, color,
                               [j](const sim::Sample& s) { return s.loads.reaction[j].tail<3>().norm(); }));
        added.back().dashed = !latches.empty();
      }
      break;
    }
    case PlotKind::energy:
      added.push_back(series(tr, "total", palette(0), [](const sim::Sample& s) { return s.energy.total(); }));
      if (!tr.empty() && tr.samples.front().energy.unattributed != 0) break;  // only the total is known
      // Every store, and the work taken out: total + dissipated is the
      // balance, flat when the energy is accounted for (the drop at
      // latch-up is the latches' damping, in "dissipated").
      added.push_back(series(tr, "kinetic", palette(1), [](const sim::Sample& s) { return s.energy.kinetic; }));
      added.push_back(series(tr, "springs", palette(2), [](const sim::Sample& s) { return s.energy.springs; }));
      added.push_back(series(tr, "latches", palette(3), [](const sim::Sample& s) { return s.energy.latches; }));
      if (scene.gravity().norm() > 0)
        added.push_back(series(tr, "gravity", palette(4), [](const sim::Sample& s) { return s.energy.gravity; }));
      if (!scene.loops.empty())
        added.push_back(series(tr, "regulator", palette(5), [](const sim::Sample& s) { return s.energy.regulator; }));
      added.push_back(series(tr, "dissipated", palette(6), [](const sim::Sample& s) { return s.energy.dissipated; }));
      added.back().dashed = true;
      if (std::none_of(tr.samples.begin(), tr.samples.end(),
                       [](const sim::Sample& s) { return s.energy.driven != 0; })) {
        added.push_back(
            series(tr, "total + dissipated", palette(7), [](const sim::Sample& s) { return s.energy.balance(); }));
      } else {
        added.push_back(series(tr, "driven", palette(8), [](const sim::Sample& s) { return s.energy.driven; }));
        added.back().dashed = true;
        added.push_back(series(tr, "total + dissipated - driven", palette(7),
                               [](const sim::Sample& s) { return s.energy.balance(); }));
      }
      added.back().dashed = true;
      break;
    case PlotKind::sensors: {
      // Each acceleration's magnitude in g.
      int column = 0, k = 0;
      for (const sim::Sensor& sensor : scene.sensors) {
        for (const sim::SensorQuantity q : sensor.measures) {
          if (q == sim::SensorQuantity::acceleration && !tr.empty() &&
              column + 2 < static_cast<int>(tr.samples.front().loads.sensor.size()))
            added.push_back(series(tr, sensor.name, palette(k++), [column](const sim::Sample& s) {
              return Eigen::Map<const sim::Vec3>(s.loads.sensor.data() + column).norm() / sim::kStandardGravity;
            }));
          column += 3;
        }
      }
      break;
    }
    case PlotKind::bus: {
      if (!model.free_floating()) break;
      // The rotation vector (solid) and the body-frame rate (dashed).
      static const char* const axes[] = {"x", "y", "z"};
      for (int a = 0; a < 3; ++a) {
        added.push_back(series(tr, std::string("rotation ") + axes[a], palette(a), [&, a](const sim::Sample& s) {
          return sim::bus_motion(model, s.y.data() + L.q(), s.q_dot.data()).rotation_vector[a];
        }));
      }
      for (int a = 0; a < 3; ++a) {
        added.push_back(series(tr, std::string("rate ") + axes[a], palette(a), [&, a](const sim::Sample& s) {
          return sim::bus_motion(model, s.y.data() + L.q(), s.q_dot.data()).rate[a];
        }));
        added.back().dashed = true;
      }
      break;
    }
  }
  for (Series& s : added) {
    if (other) {
      s.ghost = true;
      s.run = other->name;
      if (other->color != 0) s.color = other->color;
    }
    spec.series.push_back(std::move(s));
  }
}

// The spans of samples whose loads are indeterminate, each sample covering
// half the way to its neighbours.
std::vector<std::pair<double, double>> indeterminate_spans(const sim::Trajectory& tr) {
  std::vector<std::pair<double, double>> spans;
  const auto& samples = tr.samples;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].loads.determinacy != sim::Determinacy::indeterminate) continue;
    const double a = k > 0 ? 0.5 * (samples[k - 1].t + samples[k].t) : samples[k].t;
    const double b = k + 1 < samples.size() ? 0.5 * (samples[k].t + samples[k + 1].t) : samples[k].t;
    if (!spans.empty() && spans.back().second >= a)
      spans.back().second = b;
    else
      spans.emplace_back(a, b);
  }
  return spans;
}

}  // namespace

namespace {

// Each driven joint's factor up to its latch, and the factor required.
void add_margins(PlotSpec& spec, const sim::Trajectory& trajectory, const PlotChoice& choice) {
  if (!choice.torque_margins || trajectory.empty()) return;
  for (std::size_t k = 0; k < choice.torque_margins->size(); ++k) {
    const sim::JointTorqueMargin& m = (*choice.torque_margins)[k];
    Series s;
    s.label = m.joint;
    s.color = palette(static_cast<int>(k));
    for (const sim::TorqueMarginPoint& p : m.run)
      if (std::isfinite(p.factor) && p.factor > 0) s.x.push_back(p.t), s.y.push_back(p.factor);
    if (!s.x.empty()) spec.series.push_back(std::move(s));
  }
  Series required;
  required.label = "required";
  required.x = {trajectory.samples.front().t, trajectory.t_end()};
  required.y = {choice.required_factor, choice.required_factor};
  required.color = IM_COL32(150, 150, 150, 255);
  required.dashed = true;
  spec.series.push_back(std::move(required));
}

}  // namespace

PlotSpec trajectory_plot(PlotKind kind, const sim::Scene& scene, const sim::Trajectory& trajectory,
                         const PlotChoice& choice) {
  PlotSpec spec;
  spec.x_label = "time, s";
  spec.x_range = choice.time_range;
  const int n1 = scene.model.scalar_coordinates, shown = static_cast<int>(chosen_coordinates(scene.model, choice).size());
  const std::string which = shown < n1 ? " (" + std::to_string(shown) + " of " + std::to_string(n1) + " joints)" : "";
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
      spec.title = scene.name + (scene.latches().empty() ? ": hinge moments" : ": latch torques and hinge moments");
      spec.y_label = "N m (hinge moments about the hinge point)";
      break;
    case PlotKind::torque_margin:
      spec.title = scene.name + ": motorization factor of each driven joint along the run";
      spec.y_label = "driving over resistive torques, with their factors";
      spec.log_y = true;
      break;
    case PlotKind::hinge_forces:
      spec.title = scene.name + ": hinge forces (what each pin carries)";
      spec.y_label = "N";
      break;
    case PlotKind::sensors:
      spec.title = scene.name + ": the sensors' accelerations";
      spec.y_label = "|acceleration|, g";
      break;
    case PlotKind::energy:
      spec.title = scene.name + ": energy";
      spec.y_label = "J";
      break;
    case PlotKind::bus:
      spec.title = scene.name + ": the free bus's attitude (rotation vector) and rate (bus frame)";
      spec.y_label = "rad (solid), rad/s (dashed)";
      break;
  }
  for (const ComparedRun& other : choice.others)
    if (other.trajectory && !other.trajectory->empty()) add_curves(spec, kind, scene, *other.trajectory, &other, choice);
  add_curves(spec, kind, scene, trajectory, nullptr, choice);
  if (kind == PlotKind::torque_margin) add_margins(spec, trajectory, choice);
  for (const sim::LatchEvent& e : trajectory.events)
    if (spec.events.empty() || std::abs(spec.events.back() - e.t) > 1e-6) spec.events.push_back(e.t);
  if (kind == PlotKind::loads || kind == PlotKind::hinge_forces) {
    spec.shaded = indeterminate_spans(trajectory);
    spec.shaded_label = "loads indeterminate (minimum-norm)";
  }
  return spec;
}

const char* plot_kind_name(PlotKind kind) {
  switch (kind) {
    case PlotKind::angles: return "angles";
    case PlotKind::rates: return "rates";
    case PlotKind::residuals: return "loop gaps";
    case PlotKind::loads: return "loads";
    case PlotKind::energy: return "energy";
    case PlotKind::bus: return "bus";
    case PlotKind::sensors: return "sensors";
    case PlotKind::hinge_forces: return "hinge forces";
    case PlotKind::torque_margin: return "torque margin";
  }
  return "?";
}

std::vector<PlotKind> plot_kinds(const sim::Scene& scene) {
  std::vector<PlotKind> kinds{PlotKind::angles, PlotKind::rates};
  if (!scene.loops.empty()) kinds.push_back(PlotKind::residuals);
  kinds.push_back(PlotKind::loads);
  kinds.push_back(PlotKind::hinge_forces);
  kinds.push_back(PlotKind::energy);
  if (scene.model.free_floating()) kinds.push_back(PlotKind::bus);
  for (const sim::Sensor& sensor : scene.sensors)
    if (std::count(sensor.measures.begin(), sensor.measures.end(), sim::SensorQuantity::acceleration) > 0) {
      kinds.push_back(PlotKind::sensors);
      break;
    }
  return kinds;
}

std::vector<NamedPlot> trajectory_plots(const sim::Scene& scene, const sim::Trajectory& trajectory, int max_joints) {
  static const char* files[] = {"angles.png", "rates.png", "residuals.png", "loads.png",
                                "energy.png", "bus.png",   "sensors.png",   "hinge_forces.png"};
  std::vector<NamedPlot> plots;
  for (PlotKind kind : plot_kinds(scene)) {
    if ((kind == PlotKind::loads || kind == PlotKind::hinge_forces) &&
        (trajectory.empty() || trajectory.samples.front().loads.reaction.empty()))
      continue;
    if (kind == PlotKind::sensors && (trajectory.empty() || trajectory.samples.front().loads.sensor.empty())) continue;
    PlotChoice choice;
    choice.max_joints = max_joints;
    plots.push_back({kind, files[static_cast<int>(kind)], trajectory_plot(kind, scene, trajectory, choice)});
  }
  return plots;
}

}  // namespace unfurl::render
