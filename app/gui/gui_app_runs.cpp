// The workbench's runs: starting one on the simulation thread, taking its
// samples, pinning finished runs and keeping those still comparable.
#include "gui_app.hpp"

#include "scene_clearance.hpp"

namespace unfurl::app {

void GuiApp::keep_comparable_pins(const SceneShape& previous) {
  // Pinned runs stay with runs of the same shape (a study's cases, an
  // edited scene); another scene's would be read with the wrong indices.
  const SceneShape shape = scene_shape(state_.scene);
  const std::size_t before = state_.pinned.size();
  state_.pinned.erase(std::remove_if(state_.pinned.begin(), state_.pinned.end(),
                                     [&](const PinnedRun& p) { return !(p.shape == shape); }),
                      state_.pinned.end());
  if (state_.pinned.size() < before)
    state_.notice = std::to_string(before - state_.pinned.size()) + " pinned run(s) of another scene dropped";
  if (!(shape == previous)) state_.plot_coordinates.clear(), state_.time_zoom.reset();
  ++state_.plots_version;
}

void GuiApp::pin_current_run(const std::string& name) {
  if (!state_.run_pinnable()) {
    state_.notice = "not pinned: the run has not finished";
    return;
  }
  PinnedRun p;
  p.name = name.empty() ? "run " + std::to_string(state_.generation) : name;
  std::snprintf(p.name_field, sizeof p.name_field, "%s", p.name.c_str());
  p.shape = scene_shape(state_.scene);
  p.trajectory = state_.trajectory;
  p.summary = state_.progress.summary;
  // The first colour no pinned run has.
  int k = 0;
  while (k < 6 && std::any_of(state_.pinned.begin(), state_.pinned.end(),
                              [&](const PinnedRun& q) { return q.color == pinned_color(k); }))
    ++k;
  p.color = pinned_color(k < 6 ? k : static_cast<int>(state_.pinned.size()));
  state_.pinned.push_back(std::move(p));
  state_.select_runs_tab = true;
  ++state_.plots_version;
  state_.notice = "pinned " + state_.pinned.back().name;
}

void GuiApp::start_run() {
  state_.requested_generation = worker_.run(state_.scene, scene_solids(state_.scene, state_.visuals, nullptr), state_.failed_latches);
}

void GuiApp::sync_run() {
  const long before = state_.generation;
  state_.progress = worker_.sync(state_.generation, state_.trajectory, state_.ghost);
  if (state_.generation < state_.scene_first_generation) {
    // The previous scene's run, still winding down: not this scene's.
    state_.trajectory = sim::Trajectory{};
    state_.ghost = sim::Trajectory{};
    return;
  }
  if (state_.generation != before && state_.ghost.samples.size() < 2) state_.ghost = sim::Trajectory{};
  // A mode of an earlier run is not this one's: the view goes back to the run.
  if (state_.generation != before) state_.modes.shown = -1;
}

}  // namespace unfurl::app
