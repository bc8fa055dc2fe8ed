// Dynamics evaluated without the regulator, for analyses: the accelerations
// with the rigid model's loop forces, an element's generalized forces, the
// mass matrix, and the loops' gap and its Jacobian (dynamics.hpp).
#include <cmath>

#include "closure_rank.hpp"
#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim {

bool Dynamics::rigid_accelerations(const double* q, const double* w, double* w_dot) {
  if (regulator_ && !closure_rank_) return false;
  configure(q);
  body_velocities(w, true);
  if (elements_need_poses_ || regulator_) sweep_.poses(poses_);
  add_element_forces(q, w);
  if (regulator_) {
    // d: the loops' gap acceleration under every other force; the
    // accelerations pass consumes the forces, so they are added again.
    sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data());
    regulator_->residual_rate(a_, d_.data());
    closure_rank_->compute(regulator_->mobility(sweep_));
    closure_rank_->rigid_loop_forces(d_.data(), lambda_.data());
    add_element_forces(q, w);
    regulator_->apply(lambda_.data(), F_);
  }
  sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, w_dot);
  for (int c = 0; c < layout_.nv; ++c)
    if (!std::isfinite(w_dot[c])) return false;
  return true;
}

Eigen::VectorXd Dynamics::element_generalized_forces(std::size_t k, const double* q, const double* w) {
  const Model& model = scene_.model;
  configure(q);
  body_velocities(w, true);
  sweep_.poses(poses_);
  for (Vec6& f : F_) f.setZero();
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.nv);
  ElementForces out{RatesOut(Q.data()), F_};
  scene_.elements[k]->add_forces(element_state(k, q, w, poses_, v_, model.base_velocity, &sweep_), out);
  sweep_.generalized_forces(F_, Q_.data());
  for (int c = 0; c < model.nv; ++c) Q[c] += Q_[c];
  return Q;
}

Eigen::MatrixXd Dynamics::mass_matrix(const double* q) {
  const Model& model = scene_.model;
  const int n = model.nv;
  configure(q);
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c) {
    unit.setZero();
    unit[c] = 1;
    momenta_of_rates(unit.data(), false, M.col(c).data());
  }
  return M;
}

Eigen::VectorXd Dynamics::loop_gap(const double* q) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(layout_.m);
  if (!regulator_) return g;
  configure(q);
  sweep_.poses(poses_);
  regulator_->gap(poses_, g.data());
  for (int c = 0; c < layout_.m; ++c) g[c] /= regulator_->component_scale(c);
  return g;
}

Eigen::MatrixXd Dynamics::loop_jacobian(const double* q) {
  const int n = scene_.model.nv;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(layout_.m, n);
  if (!regulator_) return G;
  configure(q);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c) {
    unit.setZero();
    unit[c] = 1;
    body_velocities(unit.data(), false);
    regulator_->residual_rate(v_, G.col(c).data());
  }
  for (int r = 0; r < layout_.m; ++r) G.row(r) /= regulator_->component_scale(r);
  return G;
}

}  // namespace unfurl::sim
