// Numerical stability on stiff and extreme cases: the reference scenes
// pushed to the ends of their parameters (latch stiffness, regulator
// frequency and tuning, mass ratios), started at their singular
// configurations, run for a long time without damping, and scaled up to
// large arrays. Each case runs to the end or stops with a clear failure
// (which check, where); a time budget keeps any case from hanging.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "scene_yaml.hpp"
#include "simulation.hpp"

namespace unfurl {

struct StabilityCase {
  std::string group;  // "latch stiffness", "regulator v_max", ...
  std::string label;  // "k_L = 1e7, cvode-bdf"
  std::string scene;  // a built-in scene, or "pantograph:N" / "zfold:N" (generated)
  std::vector<Override> overrides;
  bool small = false;           // cheap: part of the test suite
  std::string expected_check;   // "" = finishes; else the check it fails ("closure", ...)
  bool probe = false;           // looking for a limit: finishing and failing a check are both fine
  bool conservative = false;    // report the energy drift
  bool branches = false;        // report which way each loop went
  bool closing_time = false;    // report how fast an open start closes
};

struct StabilityResult {
  StabilityCase spec;
  RunStatus status = RunStatus::finished;
  std::string failed_check, failure;
  double t_reached = 0, wall_time_s = 0, min_step = 0;
  long steps = 0, rhs_calls = 0;
  int bodies = 0, loop_components = 0;
  double energy_initial = 0, energy_final = 0;
  double energy_drift = std::numeric_limits<double>::quiet_NaN();  // max |E - E0| / |E0| (conservative cases)
  double max_closure_m = 0, max_closure_rad = 0;
  int latches_engaged = 0, latches_total = 0;
  bool energy_rose = false;        // a passive, non-conservative run that gained energy: not physical
  std::vector<std::string> notes;  // branches, closing time
  Trajectory trajectory;           // kept for the conservative (long) run's plot

  // Finished, or failed the expected check.
  bool as_expected() const;
};

// The whole suite, in report order. budget_s: each run's wall-time budget.
std::vector<StabilityCase> stability_cases(double budget_s);

// The scene of a case, overrides applied.
Scene stability_scene(const StabilityCase& c);

// The command line that reproduces a case.
std::string reproduce_command(const StabilityCase& c);

StabilityResult run_stability_case(const StabilityCase& c);

// The paper's diagonal tuning (16) against the full-matrix gains on the
// pantograph: the largest geometric loop gap of each along the run (the paper's run is
// let go on past the closure check to show where it goes), and the smallest
// eigenvalue a of K = W diag(W)^-1 along the full-gain run (a mode of the
// paper's tuning is stable only for a > p0 / ((p0 + 2 p1)(1 + 2 p0 p1))).
struct GainComparison {
  std::vector<double> t_full, residual_full, t_paper, residual_paper;
  std::vector<double> t_eigen, smallest_eigen;
  double routh_bound = 0;
  RunStatus paper_status = RunStatus::finished;
  std::string paper_failure;
  int paper_latches = 0, full_latches = 0;
};
GainComparison compare_gain_tunings(double budget_s);

// Which way each loop went: the joints on the loop's path that opened
// (moved by more than 0.1 rad) and those that held (within 0.01 rad).
std::vector<std::string> describe_branches(const Scene& scene, const Trajectory& trajectory);

}  // namespace unfurl
