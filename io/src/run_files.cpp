#include "unfurl/io/run_files.hpp"

#include <cmath>

#include "unfurl/io/json_writer.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::io {

void write_trajectory_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path) {
  const Model& model = scene.model;
  const StateLayout& L = trajectory.layout;
  OutputFile file(path);
  std::ostream& out = file.stream();
  // One-coordinate joints: q, its rate dq and p side by side; then each
  // position of a ball, planar or free joint with its q', then their momenta.
  const int n1 = model.scalar_coordinates;
  const bool bus = model.free_floating();
  out << "t";
  for (int c = 0; c < n1; ++c) {
    const std::string name = model.position_name(c);
    out << ",q." << name << ",dq." << name << ",p." << name;
  }
  for (int c = n1; c < model.nq; ++c) out << ",q." << model.position_name(c) << ",dq." << model.position_name(c);
  for (int c = n1; c < model.nv; ++c) out << ",p." << model.velocity_name(c);
  for (const Loop& loop : scene.loops) out << ",closure_m." << loop.name << ",closure_rad." << loop.name;
  // Each ball or free joint's orientation as a rotation vector and its
  // child's angular rate (its own frame); the system's momentum.
  std::vector<int> turning;
  for (int i = 0; i < model.size(); ++i)
    if (model.joints[i].has_quaternion()) turning.push_back(i);
  for (int i : turning) {
    for (const char* axis : {"x", "y", "z"}) out << ",rotation_vector." << model.joints[i].name << '.' << axis;
    for (const char* axis : {"x", "y", "z"}) out << ",rate." << model.joints[i].name << '.' << axis;
  }
  if (bus) {
    for (const char* axis : {"x", "y", "z"}) out << ",momentum." << axis;
    for (const char* axis : {"x", "y", "z"}) out << ",angular_momentum." << axis;
  }
  out << ",energy,energy_dissipated\n";
  for (const Sample& s : trajectory.samples) {
    out << format_number(s.t);
    for (int c = 0; c < n1; ++c)
      out << ',' << format_number(s.y[L.q() + c]) << ',' << format_number(s.q_dot[c]) << ','
          << format_number(s.y[L.p() + c]);
    for (int c = n1; c < model.nq; ++c) out << ',' << format_number(s.y[L.q() + c]) << ',' << format_number(s.q_dot[c]);
    for (int c = n1; c < model.nv; ++c) out << ',' << format_number(s.y[L.p() + c]);
    for (std::size_t l = 0; l < scene.loops.size(); ++l)
      out << ',' << format_number(s.closure[l].distance) << ',' << format_number(s.closure[l].angle);
    for (int i : turning) {
      const JointOrientation motion = joint_orientation(model, i, s.y.data() + L.q(), s.q_dot.data());
      for (const Vec3* x : {&motion.rotation_vector, &motion.rate})
        for (int a = 0; a < 3; ++a) out << ',' << format_number((*x)[a]);
    }
    if (bus)
      for (const Vec3* x : {&s.momentum.linear, &s.momentum.angular})
        for (int a = 0; a < 3; ++a) out << ',' << format_number((*x)[a]);
    out << ',' << format_number(s.energy.total()) << ',' << format_number(s.energy.dissipated) << '\n';
  }
  file.commit();
}

void write_loads_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path) {
  const Model& model = scene.model;
  const std::vector<LoadColumn>& columns = trajectory.load_columns;
  // Each joint's element columns, then its reaction; the loops' forces;
  // the columns of elements that are not on a joint.
  std::vector<std::vector<int>> of_joint(model.size());
  std::vector<int> apart;
  for (std::size_t c = 0; c < columns.size(); ++c)
    (columns[c].joint >= 0 ? of_joint[columns[c].joint] : apart).push_back(static_cast<int>(c));
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "t";
  for (int j = 0; j < model.size(); ++j) {
    for (int c : of_joint[j]) out << ',' << columns[c].name;
    for (int a = 0; a < 6; ++a) out << ",reaction." << model.joints[j].name << '.' << wrench_component_name(a);
  }
  for (const LoopComponent& c : trajectory.loop_components)
    out << ",loop_force." << scene.loops[c.loop].name << '.' << wrench_component_name(c.axis);
  for (int c : apart) out << ',' << columns[c].name;
  out << '\n';
  for (const Sample& s : trajectory.samples) {
    out << format_number(s.t);
    for (int j = 0; j < model.size(); ++j) {
      for (int c : of_joint[j]) out << ',' << format_number(s.loads.element[c]);
      for (int a = 0; a < 6; ++a) out << ',' << format_number(s.loads.reaction[j][a]);
    }
    for (double f : s.loads.loop_force) out << ',' << format_number(f);
    for (int c : apart) out << ',' << format_number(s.loads.element[c]);
    out << '\n';
  }
  file.commit();
}

void write_events_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path) {
  OutputFile file(path);
  file.stream() << "t,event,joint\n";
  for (const LatchEvent& e : trajectory.events)
    file.stream() << format_number(e.t) << ",latch," << scene.model.joints[e.joint].name << '\n';
  file.commit();
}

void write_summary_json(const Scene& scene, const RunResult& result, const RunSummary& summary,
                        const std::string& path) {
  const RunSettings& run = result.settings;
  OutputFile file(path);
  JsonWriter json(file.stream());
  json.begin_object();
  json.value("scene", scene.name).value("scene_source", scene.source);
  json.value("integrator", integrator_name(run.integrator));
  json.value("rtol", run.rtol).value("atol", run.atol);
  if (run.integrator == IntegratorKind::rk4) json.value("dt", run.dt);
  json.value("t_end", run.t_end).value("sample", run.sample);
  json.value("status", run_status_name(result.status));
  if (result.status == RunStatus::failed) {
    json.begin_object("failure");
    json.value("t", result.failure.t).value("step", result.failure.step);
    json.value("check", result.failure.check).value("message", describe(result.failure));
    json.end_object();
  }
  json.value("t_reached", summary.t_reached);
  json.value("wall_time_s", result.wall_time_s);
  json.value("steps", result.stats.steps).value("rhs_evals", result.rhs_calls);
  json.value("jacobian_product_evals", result.jacobian_product_evals);
  json.value("jacobian_evals", result.stats.jacobian_evals);
  json.value("linear_setups", result.stats.linear_setups);
  json.value("linear_iterations", result.stats.linear_iterations);
  json.value("nonlinear_iterations", result.stats.nonlinear_iterations);
  json.value("nonlinear_failures", result.stats.nonlinear_failures);
  json.value("error_test_failures", result.stats.error_test_failures);
  json.value("min_step", result.stats.min_step);
  json.value("min_step_after_restart", result.stats.min_step_after_restart);
  json.value("restarts", result.stats.restarts);
  json.value("grazes", result.stats.grazes);
  json.value("state_size", result.trajectory.layout.size());
  json.value("loop_components", result.trajectory.layout.m);
  json.begin_object("latch_times");
  for (const auto& [joint, t] : summary.latch_times) json.value(joint, t);
  json.end_object();
  json.begin_array("unlatched");
  for (const std::string& joint : summary.unlatched) json.value("", joint);
  json.end_array();
  json.value("max_closure_m", summary.max_closure_m);
  json.value("max_closure_rad", summary.max_closure_rad);
  json.value("max_closure_m_before_latch", summary.max_closure_m_before_latch);
  json.value("max_closure_rad_before_latch", summary.max_closure_rad_before_latch);
  auto peaks = [&](const char* key, const std::vector<RunSummary::NamedPeak>& list) {
    json.begin_object(key);
    for (const auto& [joint, peak] : list) {
      if (std::isnan(peak.t)) continue;  // never engaged
      json.begin_object(joint).value("value", peak.value).value("t", peak.t).end_object();
    }
    json.end_object();
  };
  peaks("latch_peak_torque", summary.latch_peak_torque);
  peaks("hinge_peak_force", summary.hinge_peak_force);
  peaks("hinge_peak_moment", summary.hinge_peak_moment);
  json.value("energy_initial", summary.energy_initial);
  json.value("energy_final", summary.energy_final);
  json.value("energy_dissipated", summary.energy_dissipated);
  json.begin_object("final_q");
  for (const auto& [joint, q] : summary.final_q) json.value(joint, q);
  json.end_object();
  if (summary.free_bus) {
    json.value("bus_peak_rate", summary.free_bus->peak_rate);
    json.value("bus_final_attitude_change", summary.free_bus->final_attitude_change);
    json.begin_object("momentum_drift");
    json.value("linear", summary.free_bus->linear_momentum_drift);
    json.value("angular", summary.free_bus->angular_momentum_drift);
    json.end_object();
  }
  json.end_object();
  file.commit();
}

}  // namespace unfurl::io
