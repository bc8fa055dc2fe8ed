// Small pieces the panels share: a number field that requests an edit of
// a scene value, the lock on what a study case's failure set, playback's
// frame and the run's end.
#pragma once

#include <string>

#include "gui_panels.hpp"

namespace unfurl::app {

inline constexpr double kFrame = 1.0 / 30;  // one frame of playback

inline double run_end(const GuiState& state) { return state.scene.run.t_end; }

// A number field for a scene value: a single click and typing (Enter or
// leaving the field commits), - and + step it; on commit, requests `path` =
// value. The tooltip says what the value is.
void value_field(const char* label, const std::string& path, double value, double step, Requests& requests,
                 double lo = 0, double hi = 0, const char* format = "%.6g", const char* help = nullptr);

// An element the shown study case's failure put in the scene: its fields
// are drawn disabled (from construction to the end of the scope) with a
// note saying why.
class FailureLock {
 public:
  FailureLock(const GuiState& state, const std::string& path)
      : state_(state),
        locked_(std::find(state.failure_elements.begin(), state.failure_elements.end(), path) !=
                state.failure_elements.end()) {
    if (locked_) ImGui::BeginDisabled();
  }
  ~FailureLock() {
    if (locked_) ImGui::EndDisabled();
  }
  FailureLock(const FailureLock&) = delete;
  FailureLock& operator=(const FailureLock&) = delete;

  void note() const {
    if (!locked_) return;
    ImGui::SameLine();
    ImGui::TextDisabled("(the case's failure: %s; set by the study file)", state_.failure_text.c_str());
  }

 private:
  const GuiState& state_;
  bool locked_;
};

}  // namespace unfurl::app
