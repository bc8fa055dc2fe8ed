// Runs a scripted session (gui_script.hpp) a few commands per frame: the
// interpreter, apart from the window's frame loop. What the commands do to
// the workbench goes through ScriptTarget.
#pragma once

#include <string>
#include <vector>

#include "gui_script.hpp"
#include "gui_state.hpp"

namespace unfurl::app {

// What a script can ask of the workbench.
class ScriptTarget {
 public:
  virtual ~ScriptTarget() = default;
  virtual GuiState& state() = 0;
  virtual void request(const Requests& requests) = 0;
  virtual bool exporting() const = 0;
  virtual void camera_preset(const std::string& name) = 0;
  virtual void screenshot(const std::string& path) = 0;
  virtual void save_frame(const std::string& path) = 0;
  virtual void quit() = 0;
};

class ScriptRunner {
 public:
  explicit ScriptRunner(std::vector<ScriptCommand> script) : script_(std::move(script)) {}

  // Runs commands until one must wait (for time, a run, an export) or a
  // screenshot was taken (the next frame should show the script's effect).
  // now: wall-clock seconds.
  void step(ScriptTarget& target, double now);
  bool finished() const { return next_ >= script_.size(); }

 private:
  std::vector<ScriptCommand> script_;
  std::size_t next_ = 0;
  double wait_until_ = 0;
};

}  // namespace unfurl::app
