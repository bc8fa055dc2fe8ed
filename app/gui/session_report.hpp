// The workbench's state as JSON, for scripted sessions and their tests:
// the runs and their latch times, the play-head, the frame rate, the edits.
#pragma once

#include <string>

#include "gui_state.hpp"

namespace unfurl::app {

// Written completely or not at all; throws std::runtime_error on failure.
void write_session_report(const GuiState& state, const std::string& path);

}  // namespace unfurl::app
