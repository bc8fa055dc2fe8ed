// The workbench's scene: loading it with the edits (and a study's case),
// saving the edited scene, reloading it when its file changes.
#include "gui_app.hpp"

#include "gui_clock.hpp"
#include "scene_options.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::app {

bool GuiApp::show_case(const std::string& id) {
  const std::string shown = state_.study->shown;
  const std::vector<sim::Override> edits = state_.edits;
  state_.study->shown = id;
  if (shown != id) state_.edits.clear();
  if (load_and_run(state_.study->study.scene)) {
    if (shown != id) state_.undo.clear(), state_.redo.clear();
    return true;
  }
  state_.study->shown = shown;
  state_.edits = edits;
  return false;
}

namespace {

// Whether a run of `a` can be drawn as the ghost of `b`: the same bodies,
// coordinates and loops (the plots index them). Latches may differ: a
// study's failure case removes one, and the nominal run is what it is
// compared with.
bool same_structure(const sim::Scene& a, const sim::Scene& b) {
  return a.name == b.name && a.model.size() == b.model.size() && a.model.nq == b.model.nq &&
         a.loops.size() == b.loops.size();
}

}  // namespace

bool GuiApp::load_and_run(const std::string& name) {
  try {
    std::vector<sim::Override> overrides = state_.command_line_set;
    overrides.insert(overrides.end(), state_.edits.begin(), state_.edits.end());
    const studies::StudyCase* shown_case =
        state_.study && !state_.study->shown.empty() ? state_.study->find_case(state_.study->shown) : nullptr;
    sim::SceneFile file = shown_case ? studies::case_scene_file(state_.study->study, *shown_case, overrides)
                                     : read_scene_named(name, overrides);
    sim::Scene& scene = file.scene;
    std::vector<std::string> injected;
    if (shown_case && shown_case->failure) injected = failure_elements(scene, *shown_case->failure);
    auto meshes = std::make_unique<render::MeshLibrary>(mesh_directories(scene));
    auto view = std::make_unique<render::SceneView>(scene, file.visuals, *meshes);
    const bool same_scene = name == state_.scene_name && same_structure(scene, state_.scene);
    const SceneShape previous_shape = scene_shape(state_.scene);
    state_.scene = std::move(scene);
    state_.visuals = std::move(file.visuals);
    state_.scene_name = name;
    state_.scene_mtime = modification_time(name);
    state_.scene_error.clear();
    state_.failure_elements = std::move(injected);
    state_.failure_text = shown_case && shown_case->failure ? shown_case->failure->describe() : "";
    state_.failed_latches =
        shown_case && shown_case->failure ? shown_case->failure->removed_latches() : std::vector<std::string>{};
    view_ = std::move(view);
    meshes_ = std::move(meshes);
    start_run();
    if (!same_scene) {
      state_.camera_fitted = false;
      state_.play_time = 0;
      state_.scene_first_generation = state_.requested_generation;
      state_.trajectory = sim::Trajectory{};
      state_.ghost = sim::Trajectory{};
      keep_comparable_pins(previous_shape);
    }
    return true;
  } catch (const std::exception& e) {
    state_.scene_error = e.what();
    return false;
  }
}

void GuiApp::watch_scene_file() {
  const double now = now_seconds();
  if (now - last_file_check_ < 1.0) return;
  last_file_check_ = now;
  const auto mtime = modification_time(state_.scene_name);
  if (mtime && state_.scene_mtime && *mtime != *state_.scene_mtime) {
    state_.scene_mtime = mtime;
    if (load_and_run(state_.scene_name)) state_.notice = "reloaded " + state_.scene_name + " (the file changed)";
  }
}

bool GuiApp::set_edits(std::vector<sim::Override> edits) {
  std::vector<sim::Override> before = std::move(state_.edits);
  state_.edits = std::move(edits);
  if (load_and_run(state_.scene_name)) return true;
  state_.edits = std::move(before);
  return false;
}

void GuiApp::save_scene(const std::string& path, bool overwrite) {
  try {
    if (state_.study && !state_.study->shown.empty())
      throw std::runtime_error("a study case is saved by its study file (its injected failure is not a scene value)");
    std::error_code ec;
    if (!overwrite && std::filesystem::exists(path, ec)) {
      state_.confirm_overwrite = path;
      state_.ask_overwrite = true;
      state_.notice = path + " exists: replace it? (Parameters tab)";
      return;
    }
    std::vector<sim::Override> overrides = state_.command_line_set;
    overrides.insert(overrides.end(), state_.edits.begin(), state_.edits.end());
    const std::string text = sim::scene_text_with(scene_text_named(state_.scene_name), state_.scene.source, overrides);
    sim::read_scene_text(text, path);  // it must read back
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!dir.empty()) io::make_directory(dir);
    io::OutputFile file(path);
    file.stream() << text;
    file.commit();
    state_.notice = "saved " + path;
  } catch (const std::exception& e) {
    state_.notice = std::string("not saved: ") + e.what();
  }
}

}  // namespace unfurl::app
