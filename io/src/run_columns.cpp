#include "unfurl/io/run_columns.hpp"
#include "unfurl/sim/elements/joint_driver.hpp"

#include <limits>

#include "unfurl/sim/momentum.hpp"

namespace unfurl::io {

namespace {

const char* const kAxes[] = {"x", "y", "z"};

void add(std::vector<RunColumn>& out, std::string name, std::string unit, std::string frame,
         std::function<double(const sim::Sample&)> value, std::function<void(sim::Sample&, double)> set = {}) {
  out.push_back({std::move(name), std::move(unit), std::move(frame), std::move(value), std::move(set)});
}

}  // namespace

std::string header_cell(const RunColumn& c) {
  if (c.unit.empty() && c.frame.empty()) return c.name;
  return c.name + " [" + c.unit + (c.unit.empty() || c.frame.empty() ? "" : "; ") + c.frame + "]";
}

std::string column_name(const std::string& cell) { return cell.substr(0, cell.find(" [")); }

std::vector<RunColumn> trajectory_columns(const sim::Scene& scene, const sim::Trajectory& tr) {
  const sim::Model& m = scene.model;
  const sim::StateLayout L = tr.layout;
  std::vector<RunColumn> out;
  add(
      out, "t", "s", "", [](const sim::Sample& s) { return s.t; }, [](sim::Sample& s, double x) { s.t = x; });
  const auto position = [&](int c) {
    add(
        out, "q." + m.position_name(c), m.position_unit(c), "", [c, L](const sim::Sample& s) { return s.y[L.q() + c]; },
        [c, L](sim::Sample& s, double x) { s.y[L.q() + c] = x; });
    const std::string unit = m.position_unit(c);
    add(
        out, "dq." + m.position_name(c), unit.empty() ? "1/s" : unit + "/s", "",
        [c](const sim::Sample& s) { return s.q_dot[c]; }, [c](sim::Sample& s, double x) { s.q_dot[c] = x; });
  };
  const auto momentum = [&](int v) {
    add(
        out, "p." + m.velocity_name(v), m.momentum_unit(v), "", [v, L](const sim::Sample& s) { return s.y[L.p() + v]; },
        [v, L](sim::Sample& s, double x) { s.y[L.p() + v] = x; });
  };
  // A one-coordinate joint's q, q' and p side by side; then the positions
  // of ball, planar and free joints with their q', then their momenta.
  for (int c = 0; c < m.nq; ++c) {
    const int j = m.joint_of_position[c];
    if (j < 0 || !m.joints[j].is_scalar()) continue;
    position(c);
    momentum(m.velocity_of(j).value);
  }
  for (int c = 0; c < m.nq; ++c)
    if (m.joint_of_position[c] < 0 || !m.joints[m.joint_of_position[c]].is_scalar()) position(c);
  for (int v = 0; v < m.nv; ++v)
    if (m.joint_of_velocity[v] < 0 || !m.joints[m.joint_of_velocity[v]].is_scalar()) momentum(v);
  for (std::size_t l = 0; l < scene.loops.size(); ++l) {
    add(
        out, "closure_gap." + scene.loops[l].name, "m", "", [l](const sim::Sample& s) { return s.closure[l].distance; },
        [l](sim::Sample& s, double x) { s.closure[l].distance = x; });
    add(
        out, "closure_angle." + scene.loops[l].name, "rad", "",
        [l](const sim::Sample& s) { return s.closure[l].angle; },
        [l](sim::Sample& s, double x) { s.closure[l].angle = x; });
  }
  // Each ball or free joint's orientation as a rotation vector and its
  // child's angular rate: derived, not read back.
  for (int i = 0; i < m.size(); ++i) {
    if (!m.joints[i].has_quaternion()) continue;
    const std::string& joint = m.joints[i].name;
    for (int a = 0; a < 3; ++a)
      add(out, "rotation_vector." + joint + "." + kAxes[a], "rad", "parent frame", [&m, i, a, L](const sim::Sample& s) {
        return sim::joint_orientation(m, i, s.y.data() + L.q(), s.q_dot.data()).rotation_vector[a];
      });
    for (int a = 0; a < 3; ++a)
      add(out, "rate." + joint + "." + kAxes[a], "rad/s", "child frame", [&m, i, a, L](const sim::Sample& s) {
        return sim::joint_orientation(m, i, s.y.data() + L.q(), s.q_dot.data()).rate[a];
      });
  }
  if (m.free_floating()) {
    for (int a = 0; a < 3; ++a)
      add(
          out, std::string("momentum.") + kAxes[a], "N s", "inertial frame",
          [a](const sim::Sample& s) { return s.momentum.linear[a]; },
          [a](sim::Sample& s, double x) { s.momentum.linear[a] = x; });
    for (int a = 0; a < 3; ++a)
      add(
          out, std::string("angular_momentum.") + kAxes[a], "N m s", "inertial frame about its origin",
          [a](const sim::Sample& s) { return s.momentum.angular[a]; },
          [a](sim::Sample& s, double x) { s.momentum.angular[a] = x; });
  }
  add(
      out, "energy", "J", "", [](const sim::Sample& s) { return s.energy.total(); },
      [](sim::Sample& s, double x) { s.energy.unattributed = x; });
  add(
      out, "energy_dissipated", "J", "", [](const sim::Sample& s) { return s.energy.dissipated; },
      [](sim::Sample& s, double x) { s.energy.dissipated = x; });
  if (!scene.elements_of<sim::JointDriver>().empty())
    add(
        out, "energy_driven", "J", "", [](const sim::Sample& s) { return s.energy.driven; },
        [](sim::Sample& s, double x) { s.energy.driven = x; });
  return out;
}

std::vector<RunColumn> load_file_columns(const sim::Scene& scene, const sim::Trajectory& tr) {
  const sim::Model& m = scene.model;
  const std::vector<sim::LoadColumn>& element = tr.load_columns;
  std::vector<RunColumn> out;
  add(
      out, "t", "s", "", [](const sim::Sample& s) { return s.t; }, [](sim::Sample& s, double x) { s.t = x; });
  // 1 where the motion determines the loads, 0 where the reactions inside
  // the loops are the minimum-norm ones, nan where it was not assessed.
  if (!scene.loops.empty())
    add(
        out, "determinate", "", "",
        [](const sim::Sample& s) {
          switch (s.loads.determinacy) {
            case sim::Determinacy::determinate:
              return 1.0;
            case sim::Determinacy::indeterminate:
              return 0.0;
            case sim::Determinacy::not_assessed:
              break;
          }
          return std::numeric_limits<double>::quiet_NaN();
        },
        [](sim::Sample& s, double x) {
          s.loads.determinacy = x == 1   ? sim::Determinacy::determinate
                                : x == 0 ? sim::Determinacy::indeterminate
                                         : sim::Determinacy::not_assessed;
        });
  const auto element_column = [&](std::size_t c) {
    add(
        out, element[c].name, element[c].unit, element[c].frame,
        [c](const sim::Sample& s) { return s.loads.element[c]; },
        [c](sim::Sample& s, double x) { s.loads.element[c] = x; });
  };
  // Each joint's element columns, then its reaction; the loops' forces;
  // the columns of elements that are not on a joint.
  std::vector<std::vector<std::size_t>> of_joint(m.size());
  for (std::size_t c = 0; c < element.size(); ++c)
    if (element[c].joint >= 0) of_joint[element[c].joint].push_back(c);
  for (int j = 0; j < m.size(); ++j) {
    for (const std::size_t c : of_joint[j]) element_column(c);
    if (!m.joints[j].has_reaction()) continue;
    for (int a = 0; a < 6; ++a)
      add(
          out, std::string(a < 3 ? "hinge_force." : "hinge_moment.") + m.joints[j].name + "." + kAxes[a % 3],
          a < 3 ? "N" : "N m", a < 3 ? "child body frame" : "child body frame about the hinge point",
          [j, a](const sim::Sample& s) { return s.loads.reaction[j][a]; },
          [j, a](sim::Sample& s, double x) { s.loads.reaction[j][a] = x; });
  }
  for (std::size_t k = 0; k < tr.loop_components.size(); ++k) {
    const sim::LoopComponent& c = tr.loop_components[k];
    add(
        out,
        std::string(c.axis < 3 ? "loop_force." : "loop_moment.") + scene.loops[c.loop].name + "." + kAxes[c.axis % 3],
        c.axis < 3 ? "N" : "N m", "split body frame", [k](const sim::Sample& s) { return s.loads.loop_force[k]; },
        [k](sim::Sample& s, double x) { s.loads.loop_force[k] = x; });
  }
  for (std::size_t c = 0; c < element.size(); ++c)
    if (element[c].joint < 0) element_column(c);
  return out;
}

std::vector<RunColumn> sensor_file_columns(const sim::Trajectory& tr) {
  std::vector<RunColumn> out;
  add(
      out, "t", "s", "", [](const sim::Sample& s) { return s.t; }, [](sim::Sample& s, double x) { s.t = x; });
  for (std::size_t c = 0; c < tr.sensor_columns.size(); ++c)
    add(
        out, tr.sensor_columns[c].name, tr.sensor_columns[c].unit, tr.sensor_columns[c].frame,
        [c](const sim::Sample& s) { return s.loads.sensor[c]; },
        [c](sim::Sample& s, double x) { s.loads.sensor[c] = x; });
  return out;
}

sim::Sample empty_sample(const sim::Scene& scene, const sim::Trajectory& tr) {
  sim::Sample s;
  s.y.assign(tr.layout.size(), 0.0);
  s.q_dot.assign(tr.layout.nq, 0.0);
  s.closure.resize(scene.loops.size());
  s.loads.element.assign(tr.load_columns.size(), 0.0);
  s.loads.reaction.assign(scene.model.size(), sim::Vec6::Zero());
  s.loads.loop_force.assign(tr.loop_components.size(), 0.0);
  s.loads.sensor.assign(tr.sensor_columns.size(), 0.0);
  return s;
}

}  // namespace unfurl::io
