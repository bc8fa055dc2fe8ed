// Helpers shared by the tests.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::test {

inline std::string asset(const std::string& relative) {
  return std::string(UNFURL_SOURCE_DIR) + "/assets/" + relative;
}

inline sim::Scene scene_file(const std::string& name, const std::vector<sim::Override>& overrides = {}) {
  return sim::load_scene_file(asset("scenes/" + name + ".yaml"), overrides);
}

// What reading a scene's text says is wrong with it, or "no error".
inline std::string scene_error(const std::string& text) {
  try {
    sim::load_scene_text(text, "bad");
  } catch (const input::InputError& e) {
    return e.what();
  }
  return "no error";
}

// A file's whole text ("" where it cannot be read).
inline std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct CommandOutcome {
  int code = -1;       // exit status, -1 when it did not exit normally
  std::string output;  // standard output and error together
};

// Runs a shell command to its end.
inline CommandOutcome run_command(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  CommandOutcome o;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) o.output.append(buf, n);
  const int status = pclose(pipe);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

// A command sent SIGINT after `seconds`: its exit status and how long it
// took to end after the signal.
struct InterruptedOutcome {
  int code = -1;
  long ms_to_end = -1;
  std::string output;
};

// `ready`, when given, is a shell condition polled every 50 ms after that
// (for up to ten minutes) before the signal: what the command must have
// done first, however slow the build (a sanitizer's) makes it. The signal
// also waits until the command catches SIGINT: a background job starts
// with SIGINT ignored, so one sent before its handler is installed (a
// loaded machine starting a sanitizer build) would be lost and the
// command would run to its end.
inline InterruptedOutcome interrupt_after(const std::string& command, double seconds, const std::string& ready = "") {
  const std::string catches_sigint = "grep -Eq '^SigCgt:.*[2367abef]$' /proc/$pid/status";
  const std::string condition = ready.empty() ? catches_sigint : "{ " + ready + "; } && " + catches_sigint;
  const std::string wait_ready = "; for i in $(seq 12000); do kill -0 $pid 2>/dev/null || break; " + condition +
                                 " && break; sleep 0.05; done";
  const CommandOutcome o = run_command("{ (" + command + ") & pid=$!; sleep " + std::to_string(seconds) + wait_ready +
                                      "; kill -INT $pid; start=$(date +%s%N); wait $pid; code=$?; "
                                      "echo \"exit $code after $(( ($(date +%s%N) - start) / 1000000 )) ms\"; }");
  InterruptedOutcome r;
  r.output = o.output;
  const auto at = o.output.rfind("exit ");
  if (at != std::string::npos) std::sscanf(o.output.c_str() + at, "exit %d after %ld ms", &r.code, &r.ms_to_end);
  return r;
}

// The entry of q named `name` (Model::position_name: a joint's name, or
// "bus.qw" for an entry of a free or ball joint) in a sample.
inline double q_of(const sim::Scene& scene, const sim::Sample& s, const std::string& name) {
  for (int c = 0; c < scene.model.nq; ++c)
    if (scene.model.position_name(c) == name) return s.y[c];
  throw std::runtime_error("no coordinate " + name);
}

// The largest difference of an angle (a position in rad) between two runs
// of one model, over the samples both have.
inline double largest_angle_difference(const sim::Model& model, const sim::RunResult& a, const sim::RunResult& b) {
  const std::size_t samples = std::min(a.trajectory.samples.size(), b.trajectory.samples.size());
  const int q = a.trajectory.layout.q();
  double largest = 0;
  for (std::size_t s = 0; s < samples; ++s)
    for (int c = 0; c < model.nq; ++c)
      if (model.position_unit(c) == "rad")
        largest = std::max(largest, std::abs(a.trajectory.samples[s].y[q + c] - b.trajectory.samples[s].y[q + c]));
  return largest;
}

// The load column `name` ("latch_torque.j1") of a run's samples, by the
// run's column description.
inline double load_of(const std::vector<sim::LoadColumn>& columns, const sim::Loads& loads, const std::string& name) {
  const int c = sim::find_load_column(columns, name);
  if (c < 0) throw std::runtime_error("no load column " + name);
  return loads.element[c];
}

// The sum of the element torques on joint j: what its hinge's reaction
// carries about the axis.
inline double joint_element_torque(const std::vector<sim::LoadColumn>& columns, const sim::Loads& loads, int j) {
  double sum = 0;
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].joint == j) sum += loads.element[c];
  return sum;
}

}  // namespace unfurl::test
