#include "newton_preconditioner.hpp"

#include <algorithm>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim {

NewtonPreconditioner::NewtonPreconditioner(Dynamics& dynamics)
    : dynamics_(dynamics),
      sweep_(dynamics.model()),
      stiffness_(dynamics.model().nv),
      damping_(dynamics.model().nv),
      diagonal_(dynamics.model().nv),
      r_(dynamics.model().nv),
      x_(dynamics.model().nv),
      rates_(dynamics.model().nv),
      w_(dynamics.model().nv),
      g_dot_(dynamics.layout().m),
      q_(dynamics.model().nq),
      spring_position_(dynamics.model().nv, -1),
      phi_(dynamics.model().size()),
      v_(dynamics.model().size()) {
  // The elements act on one-coordinate joints, whose rate is q' of their
  // position: there K couples a velocity coordinate to a position.
  const Model& model = dynamics.model();
  for (int j = 0; j < model.size(); ++j)
    if (model.joints[j].has_free_coordinate()) spring_position_[model.velocity_of(j).value] = model.position_of(j).value;
  for (int c = 0; c < model.elastic_coordinates; ++c) spring_position_[model.nv - 1 - c] = model.nq - 1 - c;
}

void NewtonPreconditioner::setup(const double* y, const double* ydot, double gamma) {
  const Model& model = dynamics_.model();
  const Scene& scene = dynamics_.scene();
  gamma_ = gamma;
  std::fill(stiffness_.begin(), stiffness_.end(), 0.0);
  std::fill(damping_.begin(), damping_.end(), 0.0);
  const double* q = y + dynamics_.layout().q();
  rates_from_position_rates(model, q, ydot + dynamics_.layout().q(), w_.data());
  // Joint stiffness and damping read coordinates only: no poses.
  const std::vector<Pose> no_poses;
  const std::vector<Vec6> no_velocities;
  for (std::size_t k = 0; k < scene.elements.size(); ++k)
    scene.elements[k]->add_joint_stiffness(
        dynamics_.element_state(k, q, w_.data(), no_poses, no_velocities, Vec6::Zero(), nullptr), RatesOut(stiffness_.data()),
        RatesOut(damping_.data()));
  // A driven joint's row of the Newton matrix is the identity (its p is
  // not a state): nothing of its elements' enters.
  for (int c = 0; c < model.nv; ++c)
    if (model.joint_of_velocity[c] >= 0 && model.joints[model.joint_of_velocity[c]].driven)
      stiffness_[c] = damping_[c] = 0;
  for (int c = 0; c < model.nv; ++c) diagonal_[c] = gamma * damping_[c] + gamma * gamma * stiffness_[c];
  std::copy_n(q, model.nq, q_.begin());
  sweep_.set_configuration(q, diagonal_.data());
}

void NewtonPreconditioner::solve(const double* r, double* z) {
  const StateLayout& L = dynamics_.layout();
  const double gamma = gamma_;
  const double* rq = r + L.q();
  const double* rp = r + L.p();
  double* zq = z + L.q();
  double* zp = z + L.p();
  // (Mtilde + gamma D + gamma^2 K) x = rp - gamma K rq, then back-substitute.
  // K and D sit on one-coordinate joints only; a ball or free joint's
  // positions follow its rates through q' = N(q) w.
  const Model& model = dynamics_.model();
  for (int c = 0; c < L.nv; ++c) {
    const int at = spring_position_[c];
    r_[c] = rp[c] - (at >= 0 ? gamma * stiffness_[c] * rq[at] : 0.0);
  }
  Eigen::Map<const Eigen::VectorXd> r_map(r_.data(), L.nv);
  Eigen::Map<Eigen::VectorXd> x_map(x_.data(), L.nv);
  sweep_.bias_pass(r_map, phi_);
  sweep_.velocity_pass(r_map, phi_, Vec6::Zero(), x_map, v_);
  // zq = rq + gamma q'(x), zp = rp - gamma (K zq + D x).
  position_rates(model, q_.data(), x_.data(), zq);
  for (int c = 0; c < L.nq; ++c) zq[c] = rq[c] + gamma * zq[c];
  for (int c = 0; c < L.nv; ++c) {
    const int at = spring_position_[c];
    zp[c] = rp[c] - (at >= 0 ? gamma * (stiffness_[c] * zq[at] + damping_[c] * x_[c]) : 0.0);
  }
  Regulator* regulator = dynamics_.regulator();
  if (!regulator) return;
  const double k_pi = regulator->k_pi(), k_v = regulator->k_v();  // (16)
  // J (k_pi zq + k_v x) by one kinematic pass: J is linear in the rates.
  for (int c = 0; c < L.nv; ++c) {
    const int at = spring_position_[c];
    rates_[c] = (at >= 0 ? k_pi * zq[at] : k_pi * gamma * x_[c]) + k_v * x_[c];
  }
  sweep_.velocities_from_rates(rates_.data(), v_);
  regulator->residual_rate(v_, g_dot_.data());
  for (int c = 0; c < L.m; ++c) z[L.u() + c] = r[L.u() + c] + gamma * g_dot_[c];
}

}  // namespace unfurl::sim
