// The modified-Lagrange PID regulator of the loop residuals g = eps pi:
//   (12)  loop force lambda = C (g + u) + D g'   (applied as -eps^T lambda)
//   (13)  u' = k_pi g + k_v g'
// Gains make every residual mode obey (s + b0)(s^2 + 2 b1 s + v_max^2) = 0,
// with b0 = p0 v_max, b1 = p1 v_max, k_pi = p0 v_max, k_v = 2 p0 p1 and
// W C = v_max^2, W D = (p0 + 2 p1) v_max of (16), where
// W = eps T A Mtilde^-1 (eps T A)^T.
//
// Two tunings:
// - full (default): C and D from the current W(q) as full matrices, so every
//   mode sits on the designed cubic however strongly the loops couple. W
//   comes from m extra passes of the sweep (O(N m), no mass matrix). Where
//   W loses rank (a branch point such as the deployed pantograph), its
//   eigenvalues are floored at eigen_floor times the largest, and modes
//   below the floor get PD action only: an integral state there is pumped
//   unstable (a < p0 / ((p0 + 2 p1)(1 + 2 p0 p1)), Routh).
// - paper: the paper's diagonal (16) with the diagonal of W at t = 0; kept to
//   show where it fails (strongly coupled loops).
#pragma once

#include <Eigen/Eigenvalues>
#include <vector>

#include "loops.hpp"
#include "sweep.hpp"

namespace unfurl {

enum class GainTuning { full, paper };

// The full tuning decomposes W in every right-hand side; bounding its size
// keeps that on the stack (no allocation) and its O(m^3) cost in check.
inline constexpr int kMaxFullGainComponents = 48;
using LoopMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxFullGainComponents, kMaxFullGainComponents>;
using LoopVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxFullGainComponents, 1>;
// Spatial vectors of every loop component's unit load at once (6 x m).
using LoopSpatial = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxFullGainComponents>;
using LoopCoordinates = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Eigen::Dynamic, kMaxFullGainComponents>;

struct RegulatorSettings {
  GainTuning gains = GainTuning::full;
  double v_max = 2000;  // rad/s, above the mechanism's highest frequency
  double p0 = 1.0;
  double p1 = 0.5;
  double eigen_floor = 1e-7;  // relative to the largest eigenvalue of W
};

class Regulator {
 public:
  // Throws std::invalid_argument when the full tuning is asked for more
  // than kMaxFullGainComponents components.
  Regulator(const Model& model, const std::vector<Loop>& loops, std::vector<LoopComponent> components,
            const RegulatorSettings& settings);

  int size() const { return static_cast<int>(components_.size()); }
  const std::vector<LoopComponent>& components() const { return components_; }
  const RegulatorSettings& settings() const { return settings_; }

  // Fixes the paper tuning's diagonal gains from W at the sweep's current
  // configuration (call at t = 0); no effect for the full tuning.
  void freeze_diagonal_gains(Sweep& sweep);

  // eps v on the active components from body velocities.
  void residual_rate(const std::vector<Vec6>& v, double* g_dot) const;

  // lambda of (12) and u' of (13) for the sweep's current configuration.
  void control(Sweep& sweep, const double* g, const double* u, const double* g_dot, double* lambda,
               double* u_dot);

  // Adds -eps^T lambda to the body forces.
  void apply(const double* lambda, std::vector<Vec6>& F) const;

  // Potential energy of the regulator's springs, (g + u)^T C (g + u) / 2.
  double energy(Sweep& sweep, const double* g, const double* u);

  // W at the sweep's configuration: the sweep's passes on the m unit loads
  // at once, O(N m).
  const LoopMatrix& mobility(Sweep& sweep);

 private:
  // Column c of W alone (the paper tuning, once, for any m).
  void mobility_column(Sweep& sweep, int c, double* column);
  void full_gains(Sweep& sweep);

  const Model& model_;
  std::vector<Loop> loops_;
  std::vector<LoopComponent> components_;
  RegulatorSettings settings_;

  Eigen::VectorXd diagonal_W0_;  // paper tuning: diag W(0)

  // Scratch, sized once.
  LoopMatrix W_;
  Eigen::SelfAdjointEigenSolver<LoopMatrix> eigen_;
  LoopVector inverse_gain_;  // 1 / max(w_k, floor)
  LoopVector strong_;        // 1 for modes with an integral state, else 0
  LoopVector a_, b_, c_;
  std::vector<LoopSpatial> loads_, phi_m_, v_m_;
  LoopCoordinates x_m_, dq_m_;
  std::vector<Vec6> F_, phi_, v_;
  std::vector<double> x_, dq_;
};

}  // namespace unfurl
