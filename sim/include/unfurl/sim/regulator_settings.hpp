// How a scene's loops are closed: the regulator's tuning (regulator.hpp)
// and the linear algebra behind its gains (closure_solver.hpp), as plain
// settings a scene file sets.
#pragma once

namespace unfurl::sim {

enum class GainTuning { full, paper };

// How the full tuning solves with R = W + delta I: dense (W by m passes,
// Cholesky), sparse (the loop-closure system over the primary graph), or
// automatic (dense while it can).
enum class ClosureSolverKind { automatic, dense, sparse };

struct RegulatorSettings {
  GainTuning gains = GainTuning::full;
  double v_max = 2000;  // rad/s, above the mechanism's highest frequency
  double p0 = 1.0;
  double p1 = 0.5;
  double regularization = 2e-6;  // delta relative to the largest eigenvalue of W(0)
  bool feedforward = true;       // full gains: cancel the residual's acceleration d
  ClosureSolverKind solver = ClosureSolverKind::automatic;

  // The feedback gains of (16): k_pi = p0 v_max, k_v = 2 p0 p1.
  double k_pi() const { return p0 * v_max; }
  double k_v() const { return 2 * p0 * p1; }
};

}  // namespace unfurl::sim
