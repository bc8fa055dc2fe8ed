#include "closure_rank.hpp"

#include "unfurl/sim/regulator.hpp"

namespace unfurl::sim {

ClosureRank::ClosureRank(const Eigen::VectorXd& scale)
    : scale_(scale), SWS_(scale.size(), scale.size()), eigen_(static_cast<Eigen::Index>(scale.size())) {}

void ClosureRank::compute(const LoopMatrix& W) {
  SWS_ = scale_.asDiagonal() * W * scale_.asDiagonal();
  if (well_conditioned()) {
    rank_ = size();
    weak_ = 0;
    decomposed_ = false;
    return;
  }
  eigen_.compute(SWS_);
  decomposed_ = true;
  const auto& Lambda = eigen_.eigenvalues();  // ascending
  const double largest = size() > 0 ? Lambda[size() - 1] : 0;
  rank_ = weak_ = 0;
  for (int i = 0; i < size(); ++i) {
    if (Lambda[i] > kRankTolerance * largest) ++rank_;
    if (Lambda[i] < kWeakDirection * largest) ++weak_;
  }
}

bool ClosureRank::well_conditioned() {
  // S W S - sigma I positive definite, sigma = kWeakDirection ||S W S||_F
  // (the Frobenius norm bounds the largest eigenvalue from above): every
  // eigenvalue lies above kWeakDirection of the largest, so W has full rank
  // and no weak direction, which two Cholesky factorizations show for less
  // than the eigen-decomposition costs. Near a branch point it fails and
  // the eigenvalues decide.
  if (size() == 0) return false;
  shifted_llt_.compute(SWS_ - kWeakDirection * SWS_.norm() * LoopMatrix::Identity(size(), size()));
  if (shifted_llt_.info() != Eigen::Success) return false;
  llt_.compute(SWS_);
  return llt_.info() == Eigen::Success;
}

ClosureRank::Vector ClosureRank::along_modes_from(int first, const double* d) const {
  // In the closure's metric: (S W S) lambda~ = S d with lambda = S lambda~,
  // solved on the eigenvectors of S W S.
  const int m = size();
  Vector Sd = scale_.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(d, m));
  if (!decomposed_) return llt_.solve(Sd);
  const auto& V = eigen_.eigenvectors();
  const auto& Lambda = eigen_.eigenvalues();
  Vector lambda_tilde = Vector::Zero(m);
  for (int i = first; i < m; ++i) lambda_tilde += (V.col(i).dot(Sd) / Lambda[i]) * V.col(i);
  return lambda_tilde;
}

ClosureRank::Vector ClosureRank::rigid(const double* d) const {
  return along_modes_from(rank_ == size() ? 0 : weak_, d);
}

void ClosureRank::rigid_loop_forces(const double* d, double* lambda) const {
  Eigen::Map<Eigen::VectorXd>(lambda, size()) = scale_.cwiseProduct(rigid(d));
}

void ClosureRank::settled_loop_forces(const double* d, double* lambda) const {
  int first = 0;
  if (decomposed_) {
    const auto& Lambda = eigen_.eigenvalues();
    while (first < size() && !(Lambda[first] > Regulator::kRedundantMode * Lambda[size() - 1])) ++first;
  }
  Eigen::Map<Eigen::VectorXd>(lambda, size()) = scale_.cwiseProduct(along_modes_from(first, d));
}

bool ClosureRank::loop_forces(const double* d, double* lambda, bool remember) {
  const int m = size();
  Vector lambda_tilde = rigid(d);
  Eigen::Map<Eigen::VectorXd> l(lambda, m);
  if (!decomposed_) {  // full rank, no weak direction: determinate
    if (remember) shaped_ = false;
    l = scale_.cwiseProduct(lambda_tilde);
    return true;
  }
  const auto& V = eigen_.eigenvectors();
  const Vector regulated = l.cwiseQuotient(scale_);
  // Only along the weak directions: along the strong ones a difference is
  // the regulator's feedback on the integrator's error in the gap, which
  // leaves the rigid forces at the state as they are.
  const Vector departure = V.leftCols(weak_).transpose() * (regulated - lambda_tilde);
  const bool departed = departure.norm() > kAgreement * lambda_tilde.norm();
  const bool weak_loaded =
      (V.leftCols(weak_).transpose() * lambda_tilde).norm() > kWeakLoaded * lambda_tilde.norm();
  const bool shaped = departed || (shaped_ && weak_loaded);
  if (remember) shaped_ = shaped;
  const bool determinate = rank_ == m && !shaped;
  if (!determinate && rank_ == m) {  // the minimum-norm forces: without the weak directions
    for (int i = 0; i < weak_; ++i) lambda_tilde -= V.col(i).dot(lambda_tilde) * V.col(i);
  }
  l = scale_.cwiseProduct(lambda_tilde);
  return determinate;
}

}  // namespace unfurl::sim
