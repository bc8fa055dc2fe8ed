#include "newton_preconditioner.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim {

NewtonPreconditioner::NewtonPreconditioner(Dynamics& dynamics)
    : dynamics_(dynamics),
      sweep_(dynamics.model()),
      plain_(dynamics.model()),
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
  // K couples a velocity coordinate to a position where the rate is q' of
  // that position: revolute, prismatic and universal joints, a compliant
  // hinge's six (its pin's stiffness acts on five of them), and elastic
  // coordinates.
  const Model& model = dynamics.model();
  for (int j = 0; j < model.size(); ++j) {
    const Joint& joint = model.joints[j];
    if (!joint.has_free_coordinate() && joint.type != JointType::universal) continue;
    for (int k = 0; k < joint.dof(); ++k)
      spring_position_[model.velocity_of(j).value + k] = model.position_of(j).value + k;
  }
  for (int c = 0; c < model.elastic_coordinates; ++c) spring_position_[model.nv - 1 - c] = model.nq - 1 - c;
  const Regulator* regulator = dynamics.regulator();
  if (!regulator || regulator->settings().gains != GainTuning::full || regulator->size() == 0) return;
  for (auto& closure : closure_)
    closure = make_armature_closure_solver(model, dynamics.scene().loops, regulator->components());
  const int m = regulator->size();
  for (auto* a : {&delta_, &Delta_, &t0_, &g_r_, &t_p_, &mu_, &du_}) a->assign(m, 0.0);
  for (auto* a : {&pair_in_, &pair_tmp_, &pair_out_}) a->assign(2 * m, 0.0);
  Q_.resize(model.nv);
  dx_.resize(model.nv);
  F_.resize(model.size());
  dv_.resize(model.size());
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
  if (closure_[0]) set_up_loops(q);
}

void NewtonPreconditioner::set_up_loops(const double* q) {
  const Regulator& regulator = *dynamics_.regulator();
  const double gamma = gamma_, v = regulator.v_max(), p0 = regulator.settings().p0, p1 = regulator.settings().p1;
  const double kappa = gamma * regulator.k_pi() + regulator.k_v();
  a1_ = gamma * v * (gamma * v + p0 + 2 * p1);
  a2_ = gamma * gamma * v * v * kappa;
  // The poles: the roots of A w^2 + (2 + a1) delta w + delta^2 in units of delta.
  const double A = 1 + a1_ + a2_, b = 2 + a1_, disc = b * b - 4 * A;
  poles_ = disc > kSeparatePoles * b * b ? 2 : 1;
  rho_[0] = poles_ == 2 ? (b - std::sqrt(disc)) / (2 * A) : b / (2 * A);
  rho_[1] = poles_ == 2 ? (b + std::sqrt(disc)) / (2 * A) : rho_[0];
  if (regulator.uses_feedforward()) plain_.set_configuration(q);
  closed_ = true;
  for (int c = 0; c < regulator.size(); ++c) Delta_[c] = regulator.delta() * std::pow(regulator.component_scale(c), 2);
  for (int k = 0; k < poles_; ++k) {
    for (int c = 0; c < regulator.size(); ++c) delta_[c] = rho_[k] * Delta_[c];
    closed_ = closed_ && closure_[k]->factorize(sweep_, delta_.data(), diagonal_.data());
  }
}

void NewtonPreconditioner::pole_sums(const std::array<const double*, 4>& in, const std::array<Numerator, 4>& first,
                                     const std::array<Numerator, 4>& second) {
  const int m = static_cast<int>(mu_.size());
  const double A = 1 + a1_ + a2_;
  auto combine = [&](auto weight, std::vector<double>& s) {
    for (int c = 0; c < m; ++c) {
      s[c] = s[m + c] = 0;
      for (int i = 0; i < 4; ++i) {
        s[c] += weight(first[i]) * in[i][c];
        s[m + c] += weight(second[i]) * in[i][c];
      }
    }
  };
  if (poles_ == 2) {
    // sum_k (W_B + rho_k Delta)^-1 N(-rho_k) / (A (rho_j - rho_k)) in.
    for (int k = 0; k < 2; ++k) {
      const double rk = rho_[k], rj = rho_[1 - k];
      combine([&](const Numerator& n) { return (n.n0 - n.n1 * rk) / (A * (rj - rk)); }, pair_in_);
      closure_[k]->solve(pair_in_.data(), k == 0 ? pair_out_.data() : pair_tmp_.data(), 2);
    }
    for (int c = 0; c < 2 * m; ++c) pair_out_[c] += pair_tmp_[c];
    return;
  }
  // A double pole: N(w) / (A (w + d)^2) = n1 / (A (w + d)) + (n0 - n1 rho) / (A (w + d)^2).
  const double rho = rho_[0];
  combine([&](const Numerator& n) { return (n.n0 - n.n1 * rho) / A; }, pair_in_);
  closure_[0]->solve(pair_in_.data(), pair_tmp_.data(), 2);
  combine([&](const Numerator& n) { return n.n1 / A; }, pair_in_);
  for (int c = 0; c < 2 * m; ++c) pair_in_[c] += Delta_[c % m] * pair_tmp_[c];
  closure_[0]->solve(pair_in_.data(), pair_out_.data(), 2);
}

void NewtonPreconditioner::close_loops(const double* r) {
  const StateLayout& L = dynamics_.layout();
  const Regulator& regulator = *dynamics_.regulator();
  const bool feedforward = regulator.uses_feedforward();
  const double gamma = gamma_, v = regulator.v_max(), A = 1 + a1_ + a2_;
  const double p0 = regulator.settings().p0, p1 = regulator.settings().p1;
  // The inputs: t0 = J B^-1 r (v_), g_r = J rq, ru and, with the
  // feedforward, t_p = J Mtilde^-1 rp.
  regulator.residual_rate(v_, t0_.data());
  const double* rq = r + L.q();
  for (int c = 0; c < L.nv; ++c) rates_[c] = spring_position_[c] >= 0 ? rq[spring_position_[c]] : 0.0;
  sweep_.velocities_from_rates(rates_.data(), dv_);
  regulator.residual_rate(dv_, g_r_.data());
  if (feedforward) {
    Eigen::Map<const Eigen::VectorXd> rp(r + L.p(), L.nv);
    Eigen::Map<Eigen::VectorXd> dx(dx_.data(), L.nv);
    plain_.bias_pass(rp, phi_);
    plain_.velocity_pass(rp, phi_, Vec6::Zero(), dx, dv_);
    regulator.residual_rate(dv_, t_p_.data());
  }
  const double* ru = r + L.u();
  // Per mode of W (w, with W_B taken as W and Delta as delta in the
  // closure's metric), mu and du are each input times N(w) / den(w), den =
  // A w^2 + (2 + a1) delta w + delta^2: the Newton system's loop rows
  // eliminated exactly (a = w / (w + delta) cancels). N = n2 w^2 + n1 delta
  // w + n0 delta^2, in units where delta = 1 (mu's n2 = 0).
  const double k_pi = regulator.k_pi(), k_v = regulator.k_v(), kappa = gamma * k_pi + k_v;
  const double b = 2 + a1_, gv2 = gamma * v * v;
  const std::array<const double*, 4> in{t0_.data(), g_r_.data(), ru, t_p_.data()};
  const std::array<Numerator, 4> force{feedforward ? Numerator{0, A, 1 + a1_} : Numerator{0, a1_ + a2_, a1_},
                                       Numerator{0, gv2 * (1 + gamma * k_pi), gv2}, Numerator{0, gv2, gv2},
                                       feedforward ? Numerator{0, -1, -1} : Numerator{0, 0, 0}};
  const std::array<Numerator, 4> gap{
      feedforward ? Numerator{0, gamma * kappa, 0} : Numerator{gamma * kappa, gamma * kappa, 0},
      Numerator{gamma * (k_pi * (1 + (p0 + 2 * p1) * gamma * v) - gamma * k_v * v * v), gamma * k_pi, 0},
      Numerator{1 + a1_, b, 1}, feedforward ? Numerator{gamma * kappa, 0, 0} : Numerator{0, 0, 0}};
  // du = n2 / A in + Delta (the rest over den).
  std::array<Numerator, 4> rest;
  for (int i = 0; i < 4; ++i) rest[i] = {0, gap[i].n1 - gap[i].n2 * b / A, gap[i].n0 - gap[i].n2 / A};
  pole_sums(in, force, rest);
  const int m = L.m;
  for (int c = 0; c < m; ++c) {
    mu_[c] = pair_out_[c];
    du_[c] = Delta_[c] * pair_out_[m + c];
    for (int i = 0; i < 4; ++i) du_[c] += gap[i].n2 / A * in[i][c];
  }
  for (Vec6& f : F_) f.setZero();
  regulator.apply(mu_.data(), F_);
  sweep_.generalized_forces(F_, Q_.data());
  Eigen::Map<const Eigen::VectorXd> Q(Q_.data(), L.nv);
  Eigen::Map<Eigen::VectorXd> dx(dx_.data(), L.nv);
  sweep_.bias_pass(Q, phi_);
  sweep_.velocity_pass(Q, phi_, Vec6::Zero(), dx, dv_);
  for (int c = 0; c < L.nv; ++c) x_[c] += dx_[c];
  for (std::size_t i = 0; i < v_.size(); ++i) v_[i] += dv_[i];
}

void NewtonPreconditioner::solve(const double* r, double* z) {
  const StateLayout& L = dynamics_.layout();
  const double gamma = gamma_;
  const double* rq = r + L.q();
  const double* rp = r + L.p();
  double* zq = z + L.q();
  double* zp = z + L.p();
  // (Mtilde + gamma D + gamma^2 K) x = rp - gamma K rq, then back-substitute.
  // K and D sit on coordinates whose rate is q' (spring_position_); a ball
  // or free joint's positions follow its rates through q' = N(q) w.
  const Model& model = dynamics_.model();
  for (int c = 0; c < L.nv; ++c) {
    const int at = spring_position_[c];
    r_[c] = rp[c] - (at >= 0 ? gamma * stiffness_[c] * rq[at] : 0.0);
  }
  Eigen::Map<const Eigen::VectorXd> r_map(r_.data(), L.nv);
  Eigen::Map<Eigen::VectorXd> x_map(x_.data(), L.nv);
  sweep_.bias_pass(r_map, phi_);
  sweep_.velocity_pass(r_map, phi_, Vec6::Zero(), x_map, v_);
  if (closed_) close_loops(r);
  // zq = rq + gamma q'(x), zp = rp - gamma (K zq + D x).
  position_rates(model, q_.data(), x_.data(), zq);
  for (int c = 0; c < L.nq; ++c) zq[c] = rq[c] + gamma * zq[c];
  for (int c = 0; c < L.nv; ++c) {
    const int at = spring_position_[c];
    zp[c] = rp[c] - (at >= 0 ? gamma * (stiffness_[c] * zq[at] + damping_[c] * x_[c]) : 0.0);
  }
  if (closed_) {
    for (int c = 0; c < L.nv; ++c) zp[c] += Q_[c];
    std::copy(du_.begin(), du_.end(), z + L.u());
    return;
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
