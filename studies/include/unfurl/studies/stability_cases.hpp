// Numerical stability on stiff and extreme cases: the reference scenes
// pushed to the ends of their parameters (latch stiffness, regulator
// frequency and tuning, mass ratios), started at their singular
// configurations, run for a long time without damping, and scaled up to
// large arrays. Each case runs to the end or stops with a clear failure
// (which check, where); a time budget keeps any case from hanging. This
// header is the catalogue of cases.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::studies {

struct StabilityCase {
  std::string group;  // "latch stiffness", "regulator v_max", ...
  std::string label;  // "k_L = 1e7, cvode-bdf"
  std::string scene;  // a built-in scene, or "pantograph:N" / "zfold:N" (generated)
  std::vector<sim::Override> overrides;
  bool small = false;           // cheap: part of the test suite
  std::string expected_check;   // "" = finishes; else the check it fails ("closure", ...)
  bool probe = false;           // looking for a limit: finishing and failing a check are both fine
  bool conservative = false;    // report the energy drift
  bool branches = false;        // report which way each loop went
  bool closing_time = false;    // report how fast an open start closes
};

// The whole suite, in report order. budget_s: each run's wall-time budget.
std::vector<StabilityCase> stability_cases(double budget_s);

// The scene of a case, overrides applied.
sim::Scene stability_scene(const StabilityCase& c);

// The command line that reproduces a case.
std::string reproduce_command(const StabilityCase& c);

}  // namespace unfurl::studies
