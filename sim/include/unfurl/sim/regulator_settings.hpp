// How a scene's loops are closed: the regulator's tuning (regulator.hpp)
// and the linear algebra behind its gains (closure_solver.hpp), as plain
// settings a scene file sets.
#pragma once

#include <optional>

namespace unfurl::sim {

enum class GainTuning { full, paper };

// How the full tuning solves with R = W + delta I: dense (W by m passes,
// Cholesky), sparse (the loop-closure system over the primary graph), or
// automatic (dense while it can).
enum class ClosureSolverKind { automatic, dense, sparse };

struct RegulatorSettings {
  GainTuning gains = GainTuning::full;
  // rad/s, above the mechanism's highest frequency; unset: chosen from the
  // mechanism's own rate (Regulator::automatic_bandwidth).
  std::optional<double> v_max;
  double p0 = 1.0;
  double p1 = 0.5;
  // delta relative to the largest eigenvalue of W(0) in the closure's
  // metric (linear components over the mechanism's length): dimensionless;
  // unset: chosen from W(0)'s weakest mode (Regulator::automatic_regularization).
  std::optional<double> regularization;
  bool feedforward = true;  // full gains: cancel the residual's acceleration d
  ClosureSolverKind solver = ClosureSolverKind::automatic;
};

}  // namespace unfurl::sim
