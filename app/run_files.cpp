#include "run_files.hpp"

#include "json_writer.hpp"
#include "number_text.hpp"
#include "output_file.hpp"

namespace unfurl::app {

void write_trajectory_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path) {
  const Model& model = scene.model;
  const StateLayout& L = trajectory.layout;
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "t";
  for (int c = 0; c < model.nq; ++c) {
    const std::string& name = model.joints[model.joint_of_coordinate[c]].name;
    out << ",q." << name << ",dq." << name << ",p." << name;
  }
  for (const Loop& loop : scene.loops) out << ",closure_m." << loop.name << ",closure_rad." << loop.name;
  out << ",energy\n";
  for (const Sample& s : trajectory.samples) {
    out << format_number(s.t);
    for (int c = 0; c < model.nq; ++c)
      out << ',' << format_number(s.y[L.q() + c]) << ',' << format_number(s.dq[c]) << ','
          << format_number(s.y[L.p() + c]);
    for (std::size_t l = 0; l < scene.loops.size(); ++l)
      out << ',' << format_number(s.closure[l].distance) << ',' << format_number(s.closure[l].angle);
    out << ',' << format_number(s.energy.total()) << '\n';
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
  json.value("jacobian_evals", result.stats.jacobian_evals);
  json.value("linear_setups", result.stats.linear_setups);
  json.value("linear_iterations", result.stats.linear_iterations);
  json.value("nonlinear_iterations", result.stats.nonlinear_iterations);
  json.value("nonlinear_failures", result.stats.nonlinear_failures);
  json.value("error_test_failures", result.stats.error_test_failures);
  json.value("min_step", result.stats.min_step);
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
  json.value("energy_initial", summary.energy_initial);
  json.value("energy_final", summary.energy_final);
  json.begin_object("final_q");
  for (const auto& [joint, q] : summary.final_q) json.value(joint, q);
  json.end_object();
  json.end_object();
  file.commit();
}

}  // namespace unfurl::app
