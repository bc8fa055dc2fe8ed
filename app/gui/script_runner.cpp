#include "script_runner.hpp"

#include <algorithm>
#include <ctime>

#include "gui_panels.hpp"
#include "session_report.hpp"
#include "unfurl/render/trajectory_plots.hpp"

namespace unfurl::app {

void ScriptRunner::step(ScriptTarget& target, double now) {
  GuiState& state = target.state();
  // Called once a frame, after it is drawn: what earlier calls changed is in it.
  changed_since_frame_ = false;
  while (next_ < script_.size()) {
    const ScriptCommand& c = script_[next_];
    const auto arg = [&](std::size_t i) { return c.args[i]; };
    // A picture waits for a frame drawn after the commands before it (the
    // script runs between drawing a frame and showing it).
    const bool picture = c.name == "screenshot" || c.name == "save_frame";
    if (picture && changed_since_frame_) return;
    static const char* const unchanging[] = {"wait", "idle", "wait_run", "wait_export", "report", "screenshot",
                                             "save_frame", "quit"};
    if (std::find(std::begin(unchanging), std::end(unchanging), c.name) == std::end(unchanging))
      changed_since_frame_ = true;
    if (c.name == "wait") {
      if (wait_until_ == 0) wait_until_ = now + std::stod(arg(0));
      if (now < wait_until_) return;
      wait_until_ = 0;
    } else if (c.name == "idle") {
      // Like wait, but the workbench is left idle: what it costs then (CPU
      // of all its threads, frames drawn) goes into the report.
      const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
      if (idle_until_ == 0) {
        idle_until_ = now + std::stod(arg(0));
        idle_cpu_start_ = cpu;
        idle_frames_start_ = state.frames;
      }
      if (now < idle_until_) return;
      state.idle_cpu_fraction = (cpu - idle_cpu_start_) / std::stod(arg(0));
      state.idle_frames = state.frames - idle_frames_start_;
      idle_until_ = 0;
    } else if (c.name == "wait_run") {
      if (!state.run_settled()) return;
    } else if (c.name == "wait_export") {
      if (target.exporting()) return;
    } else if (c.name == "cancel_export") {
      Requests r;
      r.cancel_export = true;
      target.request(r);
    } else if (c.name == "play") {
      state.playing = true;
    } else if (c.name == "pause") {
      state.playing = false;
    } else if (c.name == "speed") {
      state.speed = std::stof(arg(0));
    } else if (c.name == "loop") {
      state.loop = arg(0) == "on";
    } else if (c.name == "modes") {
      Requests r;
      r.compute_modes = true;
      target.request(r);
      state.modes.select_tab = true;
    } else if (c.name == "mode") {  // 1, 2, ...; 0: the run again
      Requests r;
      r.show_mode = std::stoi(arg(0)) - 1;
      target.request(r);
    } else if (c.name == "scrub") {
      state.play_time = std::stod(arg(0));
    } else if (c.name == "browse") {
      static const std::pair<const char*, FileField> fields[] = {
          {"open", FileField::open_scene}, {"save_scene", FileField::save_scene}, {"frame", FileField::frame},
          {"trajectory", FileField::trajectory}, {"export_dir", FileField::export_dir}, {"video", FileField::video}};
      for (const auto& [name, field] : fields)
        if (arg(0) == name) open_file_dialog(state, field);
    } else if (c.name == "ui_scale") {
      state.ui_scale = state.ui_scale_field = std::stof(arg(0));
    } else if (c.name == "camera_frame") {
      state.camera_frame = *render::parse_camera_frame(arg(0));
      state.camera_fitted = false;
    } else if (c.name == "loads") {
      state.show_loads = arg(0) == "on";
      if (c.args.size() > 1) state.load_scale = std::stof(arg(1));
    } else if (c.name == "exaggerate") {
      state.exaggeration = std::stof(arg(0));
    } else if (c.name == "orthographic") {
      state.camera.orthographic = arg(0) == "on";
    } else if (c.name == "camera") {
      target.camera_preset(arg(0));
    } else if (c.name == "set") {
      Requests r;
      r.edit = sim::Override{arg(0), arg(1)};
      target.request(r);
    } else if (c.name == "screenshot") {
      target.screenshot(arg(0));
    } else if (c.name == "save_frame") {
      target.save_frame(arg(0));
    } else if (c.name == "export") {
      Requests r;
      ExportRequest e;
      e.dir = arg(0);
      e.options.from = std::stod(arg(1));
      e.options.to = std::stod(arg(2));
      e.options.fps = std::stod(arg(3));
      if (c.args.size() > 4) e.options.video = arg(4);
      r.export_range = e;
      target.request(r);
    } else if (c.name == "open") {
      Requests r;
      r.open = arg(0);
      target.request(r);
    } else if (c.name == "undo" || c.name == "redo") {
      Requests r;
      (c.name == "undo" ? r.undo : r.redo) = true;
      target.request(r);
    } else if (c.name == "save_scene") {
      Requests r;
      r.save_scene = arg(0);
      r.overwrite = true;
      target.request(r);
    } else if (c.name == "case") {
      Requests r;
      r.open_case = arg(0);
      target.request(r);
    } else if (c.name == "plot") {
      // The tab whose name starts with the word ("loop" for "loop gaps"), or
      // "all".
      const std::vector<render::PlotKind> kinds = plot_kinds(state);
      state.plot_tab = static_cast<int>(kinds.size());
      for (std::size_t k = 0; k < kinds.size(); ++k)
        if (std::string(render::plot_kind_name(kinds[k])).rfind(arg(0), 0) == 0) state.plot_tab = static_cast<int>(k);
    } else if (c.name == "pin") {
      std::string name;
      for (const std::string& word : c.args) name += (name.empty() ? "" : " ") + word;
      Requests r;
      r.pin = name.empty() ? std::string(state.pin_name) : name;
      target.request(r);
    } else if (c.name == "unpin") {
      for (std::size_t k = arg(0) == "all" ? state.pinned.size() : 1; k > 0; --k) {
        Requests r;
        r.unpin = arg(0) == "all" ? k - 1 : std::stoul(arg(0));
        target.request(r);
      }
    } else if (c.name == "zoom") {
      if (arg(0) == "all")
        state.time_zoom.reset();
      else
        state.time_zoom = std::pair(std::stod(arg(0)), std::stod(c.args.at(1)));
      ++state.plots_version;
    } else if (c.name == "curves") {
      state.plot_coordinates.clear();
      const sim::Model& model = state.scene.model;
      for (const std::string& joint : c.args)
        for (int k = 0; k < model.nq; ++k)
          if (model.joint_of_position[k] >= 0 && model.joints[model.joint_of_position[k]].name == joint)
            state.plot_coordinates.push_back(k);
      ++state.plots_version;
    } else if (c.name == "report") {
      write_session_report(state, arg(0));
    } else if (c.name == "quit") {
      target.quit();
    }
    ++next_;
    if (c.name == "screenshot") return;
  }
}

}  // namespace unfurl::app
