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
  // Inside an `idle` command: the workbench may wait for input, for at most
  // the seconds returned by idle_left.
  bool idling() const { return idle_until_ > 0; }
  bool waiting_for_run() const { return !finished() && script_[next_].name == "wait_run"; }
  double idle_left(double now) const { return idle_until_ - now; }

 private:
  std::vector<ScriptCommand> script_;
  // A command of this step (since the frame was drawn) changed what the
  // next frame shows.
  bool changed_since_frame_ = false;
  std::size_t next_ = 0;
  double wait_until_ = 0;
  double idle_until_ = 0;
  double idle_cpu_start_ = 0;  // process CPU seconds when the idle began
  long idle_frames_start_ = 0;
};

}  // namespace unfurl::app
