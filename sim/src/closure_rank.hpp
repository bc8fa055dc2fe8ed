// Whether the motion determines the loop forces, and with them the loads
// inside the loops. The loop forces act on the mechanism through J^T lambda
// (J = eps T A); a lambda in the null space of J^T moves nothing: it is a
// self-stress that a rigid model cannot determine. That null space is W's
// (W = J Mtilde^-1 J^T, mobility.hpp), read off the eigenvalues of S W S,
// the mass-weighted mobility in the closure's metric (S = 1/length on a
// linear component, regulator.hpp), so nothing here depends on units.
//
// The loads reported are the rigid model's at the computed state: the loop
// forces that hold the loops' gap acceleration at zero, W lambda = d (d the
// gap's acceleration under every other force), not the regulator's, which
// also carry its feedback and stored integral. They are determinate where
// - W has full rank: no eigenvalue of S W S below kRankTolerance of the
//   largest (there a relative error of the state at round-off moves the
//   force along that direction by more than itself), and
// - the regulator's loop forces, which moved the mechanism, agree with the
//   rigid ones along the weak directions (below) to kAgreement of the
//   rigid ones: else the motion near a branch point was made by what the
//   regulator's regularization and gains let through, and the rigid
//   model's answer at that state is not the mechanism's. Along the strong
//   directions a difference is the regulator's feedback on the
//   integrator's error in the gap, and does not count (at rtol 1e-7 it
//   reaches 3 % on the pantograph with S W S conditioned to 1.6e-2).
// - the motion was not shaped by the regulator: after a step where its
//   forces departed along the weak directions, the state's place along
//   them (its distance from the branch point, which sets a load there as
//   1/distance) is what the regulator let through, not the mechanism's.
//   So while the rigid loads lie mostly along the weak directions (more
//   than kWeakLoaded of their norm) they stay indeterminate, even where the
//   two forces agree again; an asymmetric latch-up of the pantograph ends
//   on such states for good, with loads of 1e2..1e5 N set by the
//   regularization. The stowed start, whose loads also lie along its weak
//   directions but which no departure preceded, stays determinate.
// Elsewhere the minimum-norm loop forces are reported: the rigid ones with
// their part along the weak directions of W (eigenvalues below
// kWeakDirection of the largest, which amplify a load a thousandfold over
// the strong ones) left out, measured in the closure's metric (a force
// times the mechanism's length, as a torque).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "unfurl/sim/mobility.hpp"

namespace unfurl::sim {

class ClosureRank {
 public:
  // sqrt of the machine epsilon: half the digits of a force along the
  // direction are lost to the state's round-off.
  static constexpr double kRankTolerance = 1.5e-8;
  static constexpr double kWeakDirection = 1e-3;
  static constexpr double kAgreement = 1e-2;
  static constexpr double kWeakLoaded = 0.5;

  // scale: S, one entry per component.
  explicit ClosureRank(const Eigen::VectorXd& scale);

  // The eigen-decomposition of S W S for W at the current configuration.
  void compute(const LoopMatrix& W);

  int size() const { return static_cast<int>(scale_.size()); }
  // The closure system's rank at the last compute(): its components less
  // the redundant ones (eigenvalues of S W S at or below kRankTolerance of
  // the largest).
  int rank() const { return rank_; }

  // Replaces the regulator's loop forces lambda by the rigid model's for the
  // gap acceleration d (the minimum-norm ones where they are not
  // determinate); returns whether they are. At a step's end (remember) it
  // also updates whether the motion has been shaped by the regulator since;
  // between step ends (the samples) it only reads that, so what a run
  // reports does not depend on its sampling interval.
  bool loop_forces(const double* d, double* lambda, bool remember);
  // A new run: no departure yet.
  void forget() { shaped_ = false; }
  // The rigid model's loop forces for d, W lambda = d, whatever the
  // regulator's (where W lacks rank, those without the weak directions).
  void rigid_loop_forces(const double* d, double* lambda) const;
  // The loop forces at which the regulator's integral settles
  // (Regulator::integral_at_rest): W lambda = d along every mode it closes,
  // the weak ones that the reported loads leave out included; only
  // round-off's zeros (Regulator::kRedundantMode) are left out. Started
  // anywhere else, the integral closes the difference along a weak mode at
  // the rate a v_max, ringing at sqrt(a) v_max (regulator.hpp) for as long
  // (the 16-stage array's loops opened by 2.4e-9 m at release; the 30-stage
  // one, through SparseClosureRank's, took 400 steps for its first 0.035 s).
  void settled_loop_forces(const double* d, double* lambda) const;

 private:
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDenseComponents, 1>;
  Vector rigid(const double* d) const;  // lambda~ = S^-1 lambda of W lambda = d
  // lambda~ of W lambda = d along the eigenvectors from `first` (ascending) on.
  Vector along_modes_from(int first, const double* d) const;
  bool well_conditioned();  // factors S W S into llt_ when it is
  Eigen::VectorXd scale_;
  LoopMatrix SWS_;
  Eigen::SelfAdjointEigenSolver<LoopMatrix> eigen_;
  Eigen::LLT<LoopMatrix> shifted_llt_, llt_;
  bool decomposed_ = false;  // eigen_ holds S W S's decomposition, else llt_ its factor
  int rank_ = 0;  // eigenvalues above kRankTolerance of the largest
  int weak_ = 0;  // eigenvalues below kWeakDirection of the largest
  bool shaped_ = false;  // the state along the weak directions is the regulator's
};

}  // namespace unfurl::sim
