#include "closure_rank.hpp"

namespace unfurl::sim {

ClosureRank::ClosureRank(const Eigen::VectorXd& scale)
    : scale_(scale), SWS_(scale.size(), scale.size()), eigen_(static_cast<Eigen::Index>(scale.size())) {}

void ClosureRank::compute(const LoopMatrix& W) {
  SWS_ = scale_.asDiagonal() * W * scale_.asDiagonal();
  eigen_.compute(SWS_);
  const auto& Lambda = eigen_.eigenvalues();  // ascending
  const double largest = size() > 0 ? Lambda[size() - 1] : 0;
  rank_ = weak_ = 0;
  for (int i = 0; i < size(); ++i) {
    if (Lambda[i] > kRankTolerance * largest) ++rank_;
    if (Lambda[i] < kWeakDirection * largest) ++weak_;
  }
}

bool ClosureRank::loop_forces(const double* d, double* lambda) const {
  // In the closure's metric: (S W S) lambda~ = S d with lambda = S lambda~,
  // solved on the eigenvectors of S W S.
  const int m = size();
  const auto& V = eigen_.eigenvectors();
  const auto& Lambda = eigen_.eigenvalues();
  Vector Sd = scale_.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(d, m));
  Vector rigid = Vector::Zero(m);
  for (int i = rank_ == m ? 0 : weak_; i < m; ++i) rigid += (V.col(i).dot(Sd) / Lambda[i]) * V.col(i);
  Eigen::Map<Eigen::VectorXd> l(lambda, m);
  const Vector regulated = l.cwiseQuotient(scale_);
  bool determinate = rank_ == m && (regulated - rigid).norm() <= kAgreement * rigid.norm();
  if (!determinate && rank_ == m) {  // the minimum-norm forces: without the weak directions
    for (int i = 0; i < weak_; ++i) rigid -= V.col(i).dot(rigid) * V.col(i);
  }
  l = scale_.cwiseProduct(rigid);
  return determinate;
}

}  // namespace unfurl::sim
