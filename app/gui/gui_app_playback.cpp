// Playback: the play-head advancing with wall time and the plots' time
// window following it.
#include "gui_app.hpp"

#include <cmath>

namespace unfurl::app {

void GuiApp::advance_playback(double dt) {
  if (state_.modes.shown >= 0) state_.modes.clock = std::fmod(state_.modes.clock + dt, ModesView::kPeriod);
  if (!state_.playing) return;
  const double t_end = state_.scene.run.t_end, next = state_.play_time + dt * state_.speed;
  // While the run computes, playback waits at what is known; the play-head
  // itself keeps any time it was given (a re-run keeps it).
  if (state_.progress.running && next > state_.progress.t_reached) return;
  if (next <= t_end) {
    state_.play_time = next;
    follow_play_head();
  } else if (state_.loop) {
    state_.play_time = 0;
  } else {
    state_.play_time = t_end;
    state_.playing = false;
  }
}

void GuiApp::follow_play_head() {
  // Playback past a zoomed span turns the page: the span moves on and keeps
  // its width, so the plots show what the 3D view shows.
  if (!state_.time_zoom) return;
  auto& [t0, t1] = *state_.time_zoom;
  if (state_.play_time >= t0 && state_.play_time <= t1) return;
  const double width = t1 - t0;
  t0 = std::clamp(state_.play_time, 0.0, std::max(0.0, state_.scene.run.t_end - width));
  t1 = t0 + width;
  ++state_.plots_version;
}

}  // namespace unfurl::app
