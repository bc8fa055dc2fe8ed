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
//   is regularized: C = v^2 R^-1, D = (p0 + 2 p1) v R^-1 with R = W + delta I,
//   and the integral is scaled to match, u' = W R^-1 (k_pi g + k_v g'). A
//   mode of eigenvalue w then has the gain a = w / (w + delta) in every term,
//   s^3 + a (p0+2p1) v s^2 + a v^2 (1 + 2 a p0 p1) s + a^2 p0 v^3 = 0,
//   which is stable for every a > 0 (Routh: (p0 + 2 p1)(1 + 2 a p0 p1) > p0),
//   while the unscaled integral is unstable for a < p0 / ((p0+2p1)(1+2p0p1)).
//   Modes with w >> delta keep the designed cubic; weaker ones get softer,
//   still stable, control. delta = regularization x the largest eigenvalue
//   of W at the start. Only solves with R are needed (closure_solver.hpp).
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
#include <memory>
#include <vector>

#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/loop_components.hpp"
#include "unfurl/sim/mobility.hpp"
#include "unfurl/sim/regulator_settings.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl {

class Regulator {
 public:
  // Throws std::invalid_argument when the solver asked for cannot take the
  // scene (the dense one beyond kMaxDenseComponents components).
  Regulator(const Model& model, const std::vector<Loop>& loops, std::vector<LoopComponent> components,
            const RegulatorSettings& settings);

  int size() const { return static_cast<int>(components_.size()); }
  const std::vector<LoopComponent>& components() const { return components_; }
  const RegulatorSettings& settings() const { return settings_; }
  double delta() const { return delta_; }

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

  // lambda of (12) and u' of (13) at the sweep's current configuration,
  // from the gap g, the regulator state u, eps v and (with feedforward) d.
  // False (and NaN in lambda) if R could not be factored.
  bool control(const Sweep& sweep, const double* g, const double* u, const double* g_dot, const double* d,
               double* lambda, double* u_dot);

  // Holds the gains of the sweep's configuration (factorized now unless
  // they already are): until release_gains(), control() uses them whatever
  // q it is given and solves without refinement. What a Jacobian-vector
  // product needs (dynamics.hpp); false if R could not be factored.
  bool hold_gains(const Sweep& sweep);
  // Holds the gains of the last factorization, wherever that was.
  void hold_last_gains() { held_ = true; }
  void release_gains() { held_ = false; }
  // How many times R has been factored: unchanged, the last gains stand.
  long factorizations() const { return factorizations_; }

  // Adds -eps^T lambda to the body forces.
  void apply(const double* lambda, std::vector<Vec6>& F) const;

  // Potential energy of the regulator's springs, (g + u)^T C (g + u) / 2.
  double energy(const Sweep& sweep, const double* g, const double* u);

  // W at the sweep's configuration (for analysis; at most
  // kMaxDenseComponents components).
  const LoopMatrix& mobility(const Sweep& sweep) { return mobility_.matrix(sweep); }

 private:
  std::vector<Loop> loops_;
  std::vector<LoopComponent> components_;
  RegulatorSettings settings_;
  Mobility mobility_;
  std::unique_ptr<ClosureSolver> solver_;  // the full tuning's solves with R
  double delta_ = 0;
  Eigen::VectorXd diagonal_W0_;  // paper tuning: diag W(0)
  // The solver's factorization: for which sweep and configuration.
  bool factorize(const Sweep& sweep);
  const Sweep* factorized_sweep_ = nullptr;
  long factorized_configuration_ = 0;
  bool factorized_ok_ = false;
  bool held_ = false;
  long factorizations_ = 0;

  // Scratch, sized once: the right-hand sides of (12) and (13) side by
  // side, and R^-1 applied to them.
  Eigen::Matrix<double, Eigen::Dynamic, 2> rhs_, solved_;
};

}  // namespace unfurl
