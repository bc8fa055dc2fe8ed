// ClosureRank's tests (closure_rank.hpp) beyond kMaxDenseComponents, where
// W is not formed: on products with W (a pass of the sweep) and solves with
// two sparse factorizations (closure_solver.hpp), each O(N). In the
// closure's metric B = S W S, with lambda_max its largest eigenvalue:
// - lambda_max by power iteration, and the rank by inverse iteration on
//   B + sigma I (sigma = kNearShift lambda_max, round-off's level), both
//   started from the last configuration's vectors, so that along a run each
//   takes a few products or solves. The inverse iteration's estimate of the
//   smallest eigenvalue falls toward it from above: a rank deficit it finds
//   is certain, and one the warm start has not yet reached shows a step
//   later. The rank itself is not counted (Loads::closure_rank is -1).
// - the rigid loop forces, W lambda = d, by the solve with B + sigma I
//   refined by W products (each pass leaves sigma / (w + sigma) of the error
//   along a mode of eigenvalue w, below 1e-6 where W has full rank).
// - the weak directions (eigenvalues below mu = kWeakDirection lambda_max)
//   without their eigenvectors, through the filter mu (B + mu I)^-1, which
//   keeps mu / (w + mu) of a direction of eigenvalue w: the weak ones nearly
//   whole, the strongest to 1e-3; a solve with a second factorization,
//   R_mu = W + mu S^-2.
// - the minimum-norm loop forces by iterated Tikhonov regularization at mu:
//   kTikhonovPasses solves with R_mu, each refining the last by a W
//   product (the first solves for d itself), keep 1 - (mu / (w + mu))^3 of
//   the rigid force along a mode of eigenvalue w (all but 1e-9 of the
//   strongest, 87 % at w = mu) and bound the weak ones' by 3 |d| / mu:
//   a smooth stand-in for the dense analysis' sharp cut at mu, set by the
//   mechanism and that cut alone, not by the regulator's settings.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/mobility.hpp"
#include "unfurl/sim/regulator.hpp"

namespace unfurl::sim {

class SparseClosureRank {
 public:
  static constexpr double kNearShift = Regulator::kRedundantMode;  // round-off's zeros
  static constexpr int kTikhonovPasses = 3;

  // scale: S, one entry per component (as ClosureRank's).
  SparseClosureRank(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                    const Eigen::VectorXd& scale);

  // Assesses the sweep's configuration (its articulated inertias current);
  // false if a factorization failed, and the loads there are not assessed.
  // Only at a step's end (remember) does it keep its iterations' vectors
  // as the next start, so that what a run reports does not depend on its
  // sampling interval (as ClosureRank::loop_forces).
  bool compute(const Sweep& sweep, bool remember);
  bool full_rank() const { return full_rank_; }

  // As ClosureRank::loop_forces, at the configuration of the last compute().
  bool loop_forces(const double* d, double* lambda, bool remember);
  // A new run: no departure yet.
  void forget() { shaped_ = false; }
  // As ClosureRank::rigid_loop_forces: W lambda = d, the minimum-norm
  // forces where W lacks rank.
  void rigid_loop_forces(const double* d, double* lambda);
  // As ClosureRank::settled_loop_forces.
  void settled_loop_forces(const double* d, double* lambda);

 private:
  // x = R^-1 b for a factorization, refined by W products against W (the
  // rigid solve) `passes` more times.
  void solve(ClosureSolver& R, const double* b, int passes, Eigen::VectorXd& x);
  void rigid(const double* d);         // into rigid_: W lambda = d, or minimum_norm() without full rank
  void minimum_norm(const double* d);  // into rigid_
  // The part of lambda (forces, unscaled) along the weak directions, in the
  // closure's metric: mu (B + mu I)^-1 S^-1 lambda.
  const Eigen::VectorXd& weak_part(const Eigen::VectorXd& lambda);
  void smallest_eigenvalue(Eigen::VectorXd& x);

  int m_;
  Eigen::VectorXd scale_;
  Mobility mobility_;
  std::unique_ptr<ClosureSolver> near_, filter_;  // W + sigma S^-2, W + mu S^-2
  const Sweep* sweep_ = nullptr;
  Eigen::VectorXd largest_vector_, smallest_vector_;  // the iterations' warm starts (unit, in the closure's metric)
  Eigen::VectorXd largest_work_, smallest_work_;      // this configuration's iterates
  double largest_ = 0, mu_ = 0;
  bool full_rank_ = true;
  bool shaped_ = false;  // the state along the weak directions is the regulator's
  // Scratch, sized once.
  Eigen::VectorXd shift_, residual_, correction_, product_, rigid_, regulated_, weak_;
};

}  // namespace unfurl::sim
