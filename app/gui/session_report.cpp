#include "session_report.hpp"

#include "gui_panels.hpp"
#include "unfurl/io/json_writer.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"

namespace unfurl::app {

void write_session_report(const GuiState& state, const std::string& path) {
  io::OutputFile file(path);
  io::JsonWriter json(file.stream());
  json.begin_object();
  json.value("scene", state.scene.name).value("generation", state.generation);
  if (state.study) json.value("study_case", state.study->shown).value("study_rows", static_cast<long>(state.study->rows.size()));
  auto run = [&](const char* key, const sim::Trajectory& tr) {
    json.begin_object(key);
    json.value("samples", static_cast<long>(tr.samples.size()));
    json.value("t_end", tr.empty() ? 0.0 : tr.t_end());
    json.begin_object("latch_time");
    for (const sim::LatchEvent& e : tr.events) json.value(state.scene.model.joints[e.joint].name, e.t);
    json.end_object();
    json.end_object();
  };
  run("current", state.trajectory);
  run("previous", state.ghost);
  json.value("load_arrows", static_cast<long>(state.show_loads ? state.load_arrows_drawn : 0));
  json.value("load_legend", state.show_loads ? state.load_legend : std::string());
  // The spans of contact the timeline marks.
  json.begin_array("contacts");
  if (state.progress.summary && state.progress.summary->clearance)
    for (const sim::ClearanceContact& c : state.progress.summary->clearance->contacts) {
      json.begin_object();
      json.value("body_a", c.body_a).value("body_b", c.body_b).value("t_begin", c.t_begin).value("t_end", c.t_end);
      json.end_object();
    }
  json.end_array();
  json.begin_array("pinned");
  for (const PinnedRun& p : state.pinned) {
    json.begin_object();
    json.value("name", p.name).value("shown", p.shown);
    json.value("samples", static_cast<long>(p.trajectory.samples.size()));
    json.end_object();
  }
  json.end_array();
  // The Runs tab's table: each figure of the current run and of every
  // pinned run (null where a run lacks it).
  if (state.progress.summary) {
    json.begin_array("comparison");
    for (const ComparisonRow& row : compare_runs(*state.progress.summary, state.pinned)) {
      json.begin_object();
      json.value("figure", row.name).value("current", row.current);
      json.begin_array("pinned");
      for (double v : row.pinned) json.value("", v);
      json.end_array();
      json.end_object();
    }
    json.end_array();
  }
  if (state.time_zoom)
    json.begin_array("time_zoom").value("", state.time_zoom->first).value("", state.time_zoom->second).end_array();
  json.begin_array("plot_curves");
  for (int c : render::chosen_coordinates(state.scene.model, plot_choice(state)))
    json.value("", state.scene.model.joints[state.scene.model.joint_of_position[c]].name);
  json.end_array();
  json.value("status", state.progress.running ? "running" : sim::run_status_name(state.progress.status));
  json.value("run_wall_time_s", state.progress.wall_time_s).value("run_steps", state.progress.steps);
  json.value("edit_to_curves_s", state.curves_at > state.edited_at ? state.curves_at - state.edited_at : -1.0);
  json.value("play_time", state.play_time);
  if (state.modes.current(state.generation)) {
    json.begin_array("modes_hz");
    for (const sim::Mode& m : state.modes.result->modes) json.value("", m.frequency_hz);
    json.end_array();
  }
  json.value("mode_shown", state.modes.shown + 1).value("modes_error", state.modes.error);
  const std::vector<render::PlotKind> kinds = plot_kinds(state);
  const auto tab = static_cast<std::size_t>(state.plot_tab);
  json.value("plot", tab < kinds.size() ? render::plot_kind_name(kinds[tab]) : "all");
  json.value("camera_frame", render::camera_frame_name(state.camera_frame));
  json.value("fps", state.fps);
  json.value("frames_while_running", state.frames_while_running);
  json.value("fps_while_running",
             state.seconds_while_running > 0 ? state.frames_while_running / state.seconds_while_running : 0.0);
  json.value("worst_frame_ms_while_running", 1000 * state.worst_frame_while_running);
  json.value("idle_cpu_fraction", state.idle_cpu_fraction).value("idle_frames", state.idle_frames);
  json.value("notice", state.notice).value("export", state.export_progress.message);
  json.begin_array("failure_elements");
  for (const std::string& e : state.failure_elements) json.value("", e);
  json.end_array();
  json.begin_array("edits");
  for (const sim::Override& o : state.edits) json.value("", o.path + "=" + o.value);
  json.end_array();
  json.end_object();
  file.commit();
}

}  // namespace unfurl::app
