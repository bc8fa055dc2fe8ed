#include "unfurl/sim/mobility.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

namespace unfurl::sim {

Mobility::Mobility(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components)
    : loops_(loops),
      components_(components),
      F_(model.size()),
      phi_(model.size()),
      v_(model.size()),
      x_(model.nv),
      dq_(model.nv),
      Sx_(components.size()),
      Wx_(components.size()) {
  if (size() > kMaxDenseComponents) return;
  W_.resize(size(), size());
  for (auto* blocks : {&loads_, &phi_m_, &v_m_}) blocks->assign(model.size(), Spatial::Zero(6, size()));
  x_m_.resize(model.nv, size());
  dq_m_.resize(model.nv, size());
}

void Mobility::product(const Sweep& sweep, const double* x, double* Wx) {
  // The momentum J^T x = A^T T^T eps^T x given to the system at rest, and
  // the residual rates it causes.
  for (Vec6& f : F_) f.setZero();
  add_loop_forces(loops_, components_, x, 1.0, F_);
  sweep.force_pass(F_, x_);
  sweep.bias_pass(x_, phi_);
  sweep.velocity_pass(x_, phi_, Vec6::Zero(), dq_, v_);
  residual_rate(loops_, components_, v_, Wx);
}

const LoopMatrix& Mobility::matrix(const Sweep& sweep) {
  if (size() > kMaxDenseComponents)
    throw std::invalid_argument("W as a matrix holds at most " + std::to_string(kMaxDenseComponents) +
                                " loop components; this scene has " + std::to_string(size()));
  for (Spatial& f : loads_) f.setZero();
  for (int c = 0; c < size(); ++c) {
    const LoopComponent& lc = components_[c];
    loads_[loops_[lc.loop].body](lc.axis, c) = 1;
    loads_[loops_[lc.loop].image](lc.axis, c) = -1;
  }
  sweep.force_pass(loads_, x_m_);
  sweep.bias_pass(x_m_, phi_m_);
  sweep.velocity_pass(x_m_, phi_m_, Vec6::Zero(), dq_m_, v_m_);
  for (int r = 0; r < size(); ++r) {
    const LoopComponent& lc = components_[r];
    W_.row(r) = v_m_[loops_[lc.loop].body].row(lc.axis) - v_m_[loops_[lc.loop].image].row(lc.axis);
  }
  return W_;
}

double Mobility::largest_eigenvalue(const Sweep& sweep, const Eigen::VectorXd& scale) {
  // A fixed start keeps it deterministic; it only sets a scale, so a few
  // digits suffice. 1, 2, ..., m: not orthogonal to the top eigenvector of
  // a symmetric mechanism.
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(size(), 1, size()).normalized();
  return largest_eigenvalue(sweep, scale, x, 11, 1e-6);
}

double Mobility::largest_eigenvalue(const Sweep& sweep, const Eigen::VectorXd& scale, Eigen::VectorXd& x, int least,
                                    double tolerance) {
  // W is symmetric positive semidefinite: the Rayleigh quotient of the
  // iterates rises to the largest eigenvalue.
  double lambda = 0;
  for (int k = 0; k < 200; ++k) {
    Sx_ = scale.cwiseProduct(x);
    product(sweep, Sx_.data(), Wx_.data());
    Wx_ = scale.cwiseProduct(Wx_);
    const double next = x.dot(Wx_);
    const double norm = Wx_.norm();
    if (norm == 0) return 0;
    x = Wx_ / norm;
    if (k >= least && std::abs(next - lambda) <= tolerance * next) return next;
    lambda = next;
  }
  return lambda;
}

Eigen::VectorXd Mobility::spectrum(const Sweep& sweep, const Eigen::VectorXd& scale) {
  const int m = size();
  Eigen::MatrixXd SWS(m, m);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(m), column(m);
  for (int c = 0; c < m; ++c) {
    unit[c] = scale[c];
    product(sweep, unit.data(), column.data());
    SWS.col(c) = scale.cwiseProduct(column);
    unit[c] = 0;
  }
  // Symmetric up to the passes' round-off; the solver reads one triangle.
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(SWS, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace unfurl::sim
