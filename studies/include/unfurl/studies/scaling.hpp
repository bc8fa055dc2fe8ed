// How the cost grows with the mechanism: the right-hand side per body for
// chains, z-folds and pantographs from 10 to 10,000 bodies, and whole runs
// against size with the implicit integrators' dense and Krylov Newton
// solvers and an explicit one.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"

namespace unfurl::studies {

// A generated mechanism: "chain", "zfold" or "pantograph" of a size (links,
// panels or stages), with optional overrides.
struct ScalingScene {
  std::string family;
  int size = 0;
  std::string variant;  // "" or a label for the overrides ("dense gains")
  std::vector<std::pair<std::string, std::string>> overrides;
};
sim::Scene load_scaling_scene(const ScalingScene& s);
// "pantograph" or "pantograph (dense gains)": the family and its variant.
std::string family_label(const ScalingScene& s);

struct RhsTiming {
  ScalingScene scene;
  int bodies = 0, loop_components = 0, states = 0;
  double seconds_per_call = 0;  // median of several batches
  double ns_per_body = 0;
};

// Times y' = f(y) at a moving state with the loops slightly open.
RhsTiming time_right_hand_side(const ScalingScene& s, double seconds);

struct RunTiming {
  ScalingScene scene;
  std::string method;  // "cvode-bdf, dense Newton" ...
  int bodies = 0, states = 0;
  sim::RunStatus status = sim::RunStatus::finished;
  std::string failure;
  double t_reached = 0, wall_time_s = 0;
  long steps = 0, rhs_calls = 0, jacobians = 0, linear_iterations = 0;
  double max_closure_gap = 0;
};

RunTiming time_whole_run(const ScalingScene& s, sim::IntegratorKind integrator, sim::LinearSolverKind linear_solver,
                         double t_end, double budget_s);

}  // namespace unfurl::studies
