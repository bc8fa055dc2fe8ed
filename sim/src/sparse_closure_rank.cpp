#include "sparse_closure_rank.hpp"

#include <cmath>
#include <random>

#include "closure_rank.hpp"

namespace unfurl::sim {

namespace {

// The power iteration's estimate only sets the scale of the tests.
constexpr double kLargestTolerance = 1e-3;
// The inverse iteration stops once its estimate moves less than this share
// of itself, or after kMostInverseIterations solves.
constexpr double kSmallestTolerance = 1e-2;
constexpr int kMostInverseIterations = 10;

}  // namespace

SparseClosureRank::SparseClosureRank(const Model& model, const std::vector<Loop>& loops,
                                     const std::vector<LoopComponent>& components, const Eigen::VectorXd& scale)
    : m_(static_cast<int>(scale.size())),
      scale_(scale),
      mobility_(model, loops, components),
      near_(make_sparse_closure_solver(model, loops, components)),
      filter_(make_sparse_closure_solver(model, loops, components)) {
  // Fixed starts keep a run deterministic: 1, 2, ..., m for the largest (as
  // Mobility's), and for the smallest a spread that no symmetry of the
  // mechanism makes orthogonal to its weakest mode.
  largest_vector_ = Eigen::VectorXd::LinSpaced(m_, 1, m_).normalized();
  std::minstd_rand spread(1);
  std::uniform_real_distribution<double> uniform(-1, 1);
  smallest_vector_.resize(m_);
  for (double& x : smallest_vector_) x = uniform(spread);
  smallest_vector_.normalize();
  for (Eigen::VectorXd* v : {&shift_, &residual_, &correction_, &product_, &rigid_, &regulated_, &weak_}) v->resize(m_);
}

bool SparseClosureRank::compute(const Sweep& sweep, bool remember) {
  sweep_ = &sweep;
  Eigen::VectorXd& largest_vector = remember ? largest_vector_ : (largest_work_ = largest_vector_);
  Eigen::VectorXd& smallest_vector = remember ? smallest_vector_ : (smallest_work_ = smallest_vector_);
  largest_ = mobility_.largest_eigenvalue(sweep, scale_, largest_vector, 1, kLargestTolerance);
  if (!(largest_ > 0)) return false;
  mu_ = ClosureRank::kWeakDirection * largest_;
  shift_ = (kNearShift * largest_) * scale_.cwiseAbs2().cwiseInverse();  // sigma S^-2
  if (!near_->factorize(sweep, shift_.data())) return false;
  shift_ *= mu_ / (kNearShift * largest_);  // mu S^-2
  if (!filter_->factorize(sweep, shift_.data())) return false;
  smallest_eigenvalue(smallest_vector);
  return true;
}

void SparseClosureRank::smallest_eigenvalue(Eigen::VectorXd& x) {
  // (B + sigma I)^-1 = S^-1 (W + sigma S^-2)^-1 S^-1. Its Rayleigh quotient
  // nu never exceeds 1 / (smallest + sigma): 1 / nu - sigma bounds the
  // smallest eigenvalue from above.
  const double sigma = kNearShift * largest_, tolerance = ClosureRank::kRankTolerance * largest_;
  double previous = 0;
  full_rank_ = true;
  for (int k = 0; k < kMostInverseIterations; ++k) {
    residual_ = x.cwiseQuotient(scale_);
    near_->solve(residual_.data(), correction_.data(), 1, false);  // a direction: no refinement
    correction_ = correction_.cwiseQuotient(scale_);
    const double estimate = 1 / x.dot(correction_) - sigma;
    x = correction_.normalized();
    if (!(estimate > tolerance)) {
      full_rank_ = false;
      return;
    }
    if (std::abs(estimate - previous) <= kSmallestTolerance * estimate) return;
    previous = estimate;
  }
}

void SparseClosureRank::solve(ClosureSolver& R, const double* b, int passes, Eigen::VectorXd& x) {
  const Eigen::Map<const Eigen::VectorXd> b_(b, m_);
  // The near factorization amplifies by up to 1 / sigma: its solves are
  // refined against the joint rows' eps (closure_sparse.cpp); the filter's,
  // conditioned to 1e3, need not be.
  const bool refine = &R == near_.get();
  R.solve(b, x.data(), 1, refine);
  for (int k = 0; k < passes; ++k) {
    mobility_.product(*sweep_, x.data(), product_.data());
    residual_ = b_ - product_;
    R.solve(residual_.data(), correction_.data(), 1, refine);
    x += correction_;
  }
}

const Eigen::VectorXd& SparseClosureRank::weak_part(const Eigen::VectorXd& lambda) {
  // mu (B + mu I)^-1 S^-1 lambda = mu S^-1 R_mu^-1 S^-2 lambda
  residual_ = lambda.cwiseQuotient(scale_.cwiseAbs2());
  filter_->solve(residual_.data(), weak_.data(), 1, false);
  weak_ = mu_ * weak_.cwiseQuotient(scale_);
  return weak_;
}

void SparseClosureRank::minimum_norm(const double* d) { solve(*filter_, d, kTikhonovPasses - 1, rigid_); }

void SparseClosureRank::rigid(const double* d) {
  if (full_rank_) {
    solve(*near_, d, 1, rigid_);
  } else {
    minimum_norm(d);
  }
}

void SparseClosureRank::rigid_loop_forces(const double* d, double* lambda) {
  rigid(d);
  Eigen::Map<Eigen::VectorXd>(lambda, m_) = rigid_;
}

void SparseClosureRank::settled_loop_forces(const double* d, double* lambda) {
  // The near factorization's shift sigma lies at round-off's zeros, which
  // its refined solve leaves out (a mode of eigenvalue w keeps
  // 1 - (sigma / (w + sigma))^2 of its force).
  solve(*near_, d, 1, rigid_);
  Eigen::Map<Eigen::VectorXd>(lambda, m_) = rigid_;
}

bool SparseClosureRank::loop_forces(const double* d, double* lambda, bool remember) {
  Eigen::Map<Eigen::VectorXd> l(lambda, m_);
  regulated_ = l;
  // Without full rank the rigid forces are the minimum-norm ones (as
  // ClosureRank's), which the regulator's are then measured against.
  rigid(d);
  const double rigid_norm = rigid_.cwiseQuotient(scale_).norm();
  regulated_ -= rigid_;
  const bool departed = weak_part(regulated_).norm() > ClosureRank::kAgreement * rigid_norm;
  const bool shaped = departed || (shaped_ && weak_part(rigid_).norm() > ClosureRank::kWeakLoaded * rigid_norm);
  if (remember) shaped_ = shaped;
  const bool determinate = full_rank_ && !shaped;
  if (!determinate && full_rank_) minimum_norm(d);
  l = rigid_;
  return determinate;
}

}  // namespace unfurl::sim
