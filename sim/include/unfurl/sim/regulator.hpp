// The modified-Lagrange PID regulator of the loops, (12) and (13), acting on
// the true geometric gap g(q) (loops.hpp) where the paper integrates the
// quasi-coordinates eps pi of (9):
//   (12)  loop force lambda = C (g + u) + D eps v   (applied as -eps^T lambda)
//   (13)  u' = k_pi g + k_v eps v
// with k_pi = p0 v_max, k_v = 2 p0 p1 and W C = v_max^2, W D = (p0 + 2 p1)
// v_max of (16), W = eps T A Mtilde^-1 (eps T A)^T. Since g' = eps v (8)
// where the loop is closed, the linearization is the paper's and every
// residual mode obeys (s + b0)(s^2 + 2 b1 s + v_max^2) = 0, b0 = p0 v_max,
// b1 = p1 v_max. eps pi itself is not integrated: it drifts from the real
// gap with every integration error in q (quasi-coordinates are not
// integrable), and a regulator holding it at zero lets the loop open.
//
// Two tunings:
// - full (default): C and D from the current W(q) as full matrices, so every
//   mode sits on the designed cubic however strongly the loops couple.
//   Where W loses rank (a branch point such as the deployed pantograph) it
//   is regularized: C = v^2 R^-1, D = (p0 + 2 p1) v R^-1 with R = W + Delta,
//   and the integral is scaled to match, u' = W R^-1 (k_pi g + k_v g'). A
//   mode of eigenvalue w then has the gain a = w / (w + delta) in every term,
//   s^3 + a (p0+2p1) v s^2 + a v^2 (1 + 2 a p0 p1) s + a^2 p0 v^3 = 0,
//   which is stable for every a > 0 (Routh: (p0 + 2 p1)(1 + 2 a p0 p1) > p0),
//   while the unscaled integral is unstable for a < p0 / ((p0+2p1)(1+2p0p1)).
//   Modes with w >> delta keep the designed cubic; weaker ones get softer,
//   still stable, control. All of this is in the closure's metric, where a
//   linear component counts in units of the mechanism's length l
//   (MechanismScales): S = diag(1/l for a linear component, 1 for an
//   angular one) makes S W S of one unit, delta = regularization x its
//   largest eigenvalue at the start, and Delta = delta S^-2 (delta l^2 on a
//   linear component, delta on an angular one) is the same regularization
//   in the gap's own units. Scaling the mechanism's lengths and masses then
//   leaves every gain the same. Only solves with R are needed
//   (closure_solver.hpp).
//   With feedforward (default) the loop force also carries R^-1 d, d = eps a
//   the residual's acceleration under every other force (the sweep's
//   accelerations, loop forces left out): W lambda then cancels d in every
//   strong mode, and the PID corrects only what is left. Without it the
//   residual answers d with the designed error g ~ d' / (p0 v_max^3) (about
//   1e-8 m on the four-bar at v_max = 5000); with it the gap is held at
//   the integrator's tolerance. The feedforward is a force the constraint
//   needs, not feedback, so the cubic and the Routh argument are unchanged.
// - paper: the paper's diagonal (16) with the diagonal of W at t = 0 and the
//   unscaled integral; kept to show where it fails (strongly coupled loops).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <vector>

#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/loop_components.hpp"
#include "unfurl/sim/mobility.hpp"
#include "unfurl/sim/regulator_settings.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

class Regulator {
 public:
  // v_max: the bandwidth (the settings' or automatic_bandwidth()); length:
  // the mechanism's (MechanismScales). Throws std::invalid_argument when
  // the solver asked for cannot take the scene (the dense one beyond
  // kMaxDenseComponents components).
  Regulator(const Model& model, const std::vector<Loop>& loops, std::vector<LoopComponent> components,
            const RegulatorSettings& settings, double v_max, double length);

  // The bandwidth chosen for a mechanism whose fastest own rate is `rate`
  // (rad/s) when the scene sets none: v_max must lie well above the
  // mechanism's frequencies (METHOD.md).
  static double automatic_bandwidth(double rate) { return kBandwidthPerRate * rate; }
  static constexpr double kBandwidthPerRate = 25;

  // The regularization chosen for a mechanism whose weakest loop mode at
  // the start (an eigenvalue of S W(0) S over the largest, round-off's
  // zeros of exactly redundant equations left out) is `weakest_mode`:
  // delta closes a mode of eigenvalue w with the gain w / (w + delta), and
  // a loop released next to a branch point moves along modes that vanish
  // there (the generated lazy-tongs' weakest: 1.7e-6 at 3 stages, 1.5e-8
  // at 10, 1.2e-10 at 30, 1.8e-13 at 100). Far above it the loop lags the
  // rigid mechanism's: 30 stages at 2e-6 (17,000 times its weakest) ended
  // 1.9e-3 rad from a run at 2e-12 after 6.2 s, at 2e-8 (170 times)
  // 1.4e-6 rad; 10 stages' first 6 s at 2e-6 (130 times) 1.5e-7 rad from
  // a run at 2e-11, at ten times its weakest 5.4e-9 (rtol 1e-10). It is kept
  // between kFinestRegularization, below which a latch-up at the deployed
  // branch point loses its loop (30 stages at 2e-11) and the right-hand
  // side's round-off floor passes 1e-10 (2.2e-10 at 2e-9, 30 stages), and
  // kCoarsestRegularization, the reference scenes' (SCENES.md).
  static double automatic_regularization(double weakest_mode) {
    return std::clamp(kRegularizationPerWeakestMode * weakest_mode, kFinestRegularization, kCoarsestRegularization);
  }
  static constexpr double kRegularizationPerWeakestMode = 10;
  static constexpr double kFinestRegularization = 2e-9;
  static constexpr double kCoarsestRegularization = 2e-6;
  // Eigenvalues of S W S at or below this share of the largest are the
  // round-off of exact zeros (measured: below 1e-16 on redundant rods and
  // at the stowed pantograph's branch point, where the weakest real mode of
  // a 100-stage array lies at 1.8e-13).
  static constexpr double kRedundantMode = 1e-14;
  // Beyond this many components W's spectrum costs more than a run (O(m^3))
  // and the finest regularization is taken.
  static constexpr int kMaxSpectrumComponents = 1200;

  int size() const { return static_cast<int>(components_.size()); }
  const std::vector<LoopComponent>& components() const { return components_; }
  const RegulatorSettings& settings() const { return settings_; }
  // The bandwidth in use, and the feedback gains of (16): k_pi = p0 v_max,
  // k_v = 2 p0 p1.
  double v_max() const { return v_max_; }
  double k_pi() const { return settings_.p0 * v_max_; }
  double k_v() const { return 2 * settings_.p0 * settings_.p1; }
  // delta (1 / (kg m^2)): regularization x the largest eigenvalue of S W S at the start.
  double delta() const { return delta_; }
  // The regularization in use (the settings' or automatic_regularization()),
  // dimensionless; known after calibrate().
  double regularization() const { return regularization_; }
  // What a component's gap is measured against: the mechanism's length for
  // a linear one, 1 for an angular one.
  double component_scale(int c) const { return components_[c].axis < 3 ? length_ : 1.0; }

  // Fixes what the gains take from W at the start (call at the sweep's
  // initial configuration): delta for the full tuning, diag W(0) for the
  // paper's.
  void calibrate(const Sweep& sweep);

  // eps v (8) on the active components from body velocities.
  void residual_rate(const std::vector<Vec6>& v, double* g_dot) const;

  // The geometric gap g(q) on the active components from body poses.
  void gap(const std::vector<Pose>& poses, double* g) const;

  // Whether control() wants the residual's acceleration d.
  bool uses_feedforward() const { return settings_.gains == GainTuning::full && settings_.feedforward; }

  // Factors R = W + delta I for the sweep's configuration, which the caller
  // names by `configuration` (a key that changes whenever q does): at the
  // key it last factored for it keeps what it has. False if R could not be
  // factored.
  bool factorize(const Sweep& sweep, long configuration);
  // Which gains control() and energy() use:
  // - current: those of the last factorize(), solved with refinement;
  // - held: the same factorization applied at another state, solved
  //   without refinement: what a Jacobian-vector product needs (a linear
  //   stand-in for R^-1 there, dynamics.hpp).
  enum class Gains { current, held };

  // lambda of (12) and u' of (13) from the gap g, the regulator state u,
  // eps v and (with feedforward) d, with the gains of the last factorize().
  void control(const double* g, const double* u, const double* g_dot, const double* d, Gains gains, double* lambda,
               double* u_dot);

  // How many times R has been factored (statistics), and the key of the
  // configuration it was last factored for.
  long factorizations() const { return factorizations_; }
  long factorized_configuration() const { return factorized_configuration_; }

  // The integral state u at which (12) gives the loop forces `lambda` with
  // the loop closed and at rest (g = g' = 0): v^2 u + d = R lambda. With
  // the rigid forces (W lambda = d) it is u = Delta lambda / v^2, where
  // the integral settles; starting there, the regulator's forces are the
  // rigid ones from t = 0 instead of lagging them by Delta's share while
  // the integral builds up. Full tuning with feedforward only. W_lambda:
  // W lambda (W formed, or by mobility_product()).
  void integral_at_rest(const double* W_lambda, const double* lambda, const double* d, double* u) const;
  // W x by a pass of the sweep, W not formed (its articulated inertias current).
  void mobility_product(const Sweep& sweep, const double* x, double* Wx);

  // Adds -eps^T lambda to the body forces.
  void apply(const double* lambda, std::vector<Vec6>& F) const;

  // Potential energy of the regulator's springs, (g + u)^T C (g + u) / 2,
  // with the gains of the last factorize().
  double energy(const double* g, const double* u);

  // W at the sweep's configuration (for analysis; at most
  // kMaxDenseComponents components).
  const LoopMatrix& mobility(const Sweep& sweep) { return mobility_.matrix(sweep); }
  // The same where the sweep's configuration has the key `configuration`:
  // the W the last factorize() formed if it was for that key.
  const LoopMatrix& mobility(const Sweep& sweep, long configuration);

 private:
  // The weakest eigenvalue of S W S at the sweep's configuration over the
  // largest, exactly redundant directions left out (0 beyond
  // kMaxSpectrumComponents).
  double weakest_mode(const Sweep& sweep, const Eigen::VectorXd& scale);

  std::vector<Loop> loops_;
  std::vector<LoopComponent> components_;
  RegulatorSettings settings_;
  double v_max_;
  double length_;
  Mobility mobility_;
  std::unique_ptr<ClosureSolver> solver_;  // the full tuning's solves with R
  double regularization_ = 0;
  double delta_ = 0;
  Eigen::VectorXd Delta_;  // delta S^-2, per component
  Eigen::VectorXd diagonal_W0_;  // paper tuning: diag W(0)
  // The configuration key of the last factorization, and its outcome.
  long factorized_configuration_ = -1;
  bool factorized_ok_ = false;
  long factorizations_ = 0;

  // Scratch, sized once: the right-hand sides of (12) and (13) side by
  // side, and R^-1 applied to them.
  Eigen::Matrix<double, Eigen::Dynamic, 2> rhs_, solved_;
};

}  // namespace unfurl::sim
