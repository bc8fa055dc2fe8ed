// The Modes tab's work: the modes of the current run's deployed end, and a
// mode drawn as a motion in the view.
#include "gui_app.hpp"

namespace unfurl::app {

void GuiApp::compute_modes() {
  ModesView& v = state_.modes;
  v.error.clear();
  if (!state_.run_pinnable()) {
    v.error = "the modes need a finished run";
    return;
  }
  try {
    const sim::LinearizationState end = sim::state_of_run(state_.scene, state_.trajectory, state_.trajectory.t_end());
    v.result = sim::linear_modes(state_.scene, end.q, end.engaged);
    v.generation = state_.generation;
    v.shown = -1;
  } catch (const std::exception& e) {
    v.error = std::string("no modes: ") + e.what();
  }
}

void GuiApp::show_mode(int k) {
  ModesView& v = state_.modes;
  if (k < 0 || !v.current(state_.generation) || k >= static_cast<int>(v.result->modes.size())) {
    v.shown = -1;
    return;
  }
  try {
    v.animation = sim::mode_animation(state_.scene, *v.result, k, v.amplitude, ModesView::kPeriod, 120);
    v.shown = k;
  } catch (const std::exception& e) {
    v.error = std::string("cannot draw the mode: ") + e.what();
    v.shown = -1;
  }
}

}  // namespace unfurl::app
