#include "regulator.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace unfurl {

Regulator::Regulator(const Model& model, const std::vector<Loop>& loops,
                     std::vector<LoopComponent> components, const RegulatorSettings& settings)
    : model_(model),
      loops_(loops),
      components_(std::move(components)),
      settings_(settings),
      diagonal_W0_(Eigen::VectorXd::Ones(size())),
      F_(model.size()),
      phi_(model.size()),
      v_(model.size()),
      x_(model.nq),
      dq_(model.nq) {
  if (settings_.gains != GainTuning::full) return;
  if (size() > kMaxFullGainComponents)
    throw std::invalid_argument("the full-matrix regulator gains handle at most " +
                                std::to_string(kMaxFullGainComponents) + " loop components; this scene has " +
                                std::to_string(size()));
  W_.resize(size(), size());
  for (LoopVector* v : {&inverse_gain_, &strong_, &a_, &b_, &c_}) v->resize(size());
  for (auto* blocks : {&loads_, &phi_m_, &v_m_}) blocks->assign(model.size(), LoopSpatial::Zero(6, size()));
  x_m_.resize(model.nq, size());
  dq_m_.resize(model.nq, size());
}

void Regulator::mobility_column(Sweep& sweep, int c, double* column) {
  // The residual rates eps v caused by the momentum J^T e_c =
  // A^T T^T eps^T e_c on a body system at rest.
  const Vec6 at_rest = Vec6::Zero();
  for (Vec6& f : F_) f.setZero();
  const LoopComponent& lc = components_[c];
  F_[loops_[lc.loop].body][lc.axis] = 1;
  F_[loops_[lc.loop].image][lc.axis] = -1;
  sweep.generalized_forces(F_, x_.data());
  sweep.bias(x_.data(), phi_);
  sweep.velocities(x_.data(), phi_, at_rest, dq_.data(), v_);
  residual_rate(v_, column);
}

const LoopMatrix& Regulator::mobility(Sweep& sweep) {
  for (LoopSpatial& f : loads_) f.setZero();
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

void Regulator::freeze_diagonal_gains(Sweep& sweep) {
  if (settings_.gains != GainTuning::paper) return;
  std::vector<double> column(size());
  for (int c = 0; c < size(); ++c) {
    mobility_column(sweep, c, column.data());
    diagonal_W0_[c] = column[c];
  }
}

void Regulator::residual_rate(const std::vector<Vec6>& v, double* g_dot) const {
  for (int c = 0; c < size(); ++c) {
    const LoopComponent& lc = components_[c];
    g_dot[c] = v[loops_[lc.loop].body][lc.axis] - v[loops_[lc.loop].image][lc.axis];
  }
}

void Regulator::full_gains(Sweep& sweep) {
  eigen_.compute(mobility(sweep));
  const auto& w = eigen_.eigenvalues();
  const double floor =
      settings_.eigen_floor * std::max(w(size() - 1), std::numeric_limits<double>::min());
  for (int k = 0; k < size(); ++k) {
    inverse_gain_(k) = 1.0 / std::max(w(k), floor);
    strong_(k) = w(k) >= floor ? 1.0 : 0.0;
  }
}

void Regulator::control(Sweep& sweep, const double* g, const double* u, const double* g_dot,
                        double* lambda, double* u_dot) {
  const double v = settings_.v_max, p0 = settings_.p0, p1 = settings_.p1;
  const double k_pi = p0 * v, k_v = 2 * p0 * p1;  // (16)
  const int m = size();
  Eigen::Map<const Eigen::VectorXd> g_(g, m), u_(u, m), gd_(g_dot, m);
  Eigen::Map<Eigen::VectorXd> lambda_(lambda, m), ud_(u_dot, m);
  if (settings_.gains == GainTuning::paper) {
    // C_j = v^2 / W_jj, D_j = (p0 + 2 p1) v / W_jj (16)
    lambda_ = ((v * v) * (g_ + u_) + ((p0 + 2 * p1) * v) * gd_).cwiseQuotient(diagonal_W0_);
    ud_ = k_pi * g_ + k_v * gd_;  // (13)
    return;
  }
  full_gains(sweep);
  const auto& V = eigen_.eigenvectors();
  // In W's eigenbasis: a = V^T g, b = V^T u, c = V^T g'.
  a_.noalias() = V.transpose() * g_;
  b_.noalias() = V.transpose() * u_;
  c_.noalias() = V.transpose() * gd_;
  // C = v^2 W^-1, D = (p0 + 2 p1) v W^-1 on the floored spectrum; u only
  // acts on the modes that keep an integral state.
  b_ = (v * v) * (a_ + strong_.cwiseProduct(b_)) + ((p0 + 2 * p1) * v) * c_;
  lambda_.noalias() = V * inverse_gain_.cwiseProduct(b_);
  a_ = strong_.cwiseProduct(k_pi * a_ + k_v * c_);
  ud_.noalias() = V * a_;
}

void Regulator::apply(const double* lambda, std::vector<Vec6>& F) const {
  for (int c = 0; c < size(); ++c) {
    const LoopComponent& lc = components_[c];
    F[loops_[lc.loop].body][lc.axis] -= lambda[c];
    F[loops_[lc.loop].image][lc.axis] += lambda[c];
  }
}

double Regulator::energy(Sweep& sweep, const double* g, const double* u) {
  const int m = size();
  const double v2 = settings_.v_max * settings_.v_max;
  Eigen::Map<const Eigen::VectorXd> g_(g, m), u_(u, m);
  if (settings_.gains == GainTuning::paper)
    return 0.5 * v2 * (g_ + u_).cwiseAbs2().cwiseQuotient(diagonal_W0_).sum();
  full_gains(sweep);
  const auto& V = eigen_.eigenvectors();
  const LoopVector s = V.transpose() * g_ + strong_.cwiseProduct(V.transpose() * u_);
  return 0.5 * v2 * s.cwiseAbs2().cwiseProduct(inverse_gain_).sum();
}

}  // namespace unfurl
