#include "newton_preconditioner.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl {

NewtonPreconditioner::NewtonPreconditioner(Dynamics& dynamics)
    : dynamics_(dynamics),
      sweep_(dynamics.model()),
      stiffness_(dynamics.model().nv),
      damping_(dynamics.model().nv),
      diagonal_(dynamics.model().nv),
      r_(dynamics.model().nv),
      x_(dynamics.model().nv),
      rates_(dynamics.model().nv),
      g_dot_(dynamics.layout().m),
      q_(dynamics.model().nq),
      phi_(dynamics.model().size()),
      v_(dynamics.model().size()) {}

void NewtonPreconditioner::setup(const double* y, const double* ydot, double gamma) {
  const Scene& scene = dynamics_.scene();
  const Model& model = scene.model;
  gamma_ = gamma;
  std::fill(stiffness_.begin(), stiffness_.end(), 0.0);
  std::fill(damping_.begin(), damping_.end(), 0.0);
  const double* q = y + dynamics_.layout().q();
  for (const JointSpring& s : scene.springs) {
    const int c = model.coordinate[s.joint];
    stiffness_[c] += std::max(0.0, s.local_stiffness(q[c]));  // a rising stretch of a curve: none
    damping_[c] += s.damping;
  }
  const double* dq = ydot + dynamics_.layout().q();
  for (const JointFriction& f : scene.friction) {
    const int c = model.coordinate[f.joint];
    // The tanh's slope; 0 far out on its flat part (no inf * 0).
    const double x = dq[c] / f.velocity_scale;
    const double sech = std::abs(x) < 30 ? 1 / std::cosh(x) : 0.0;
    damping_[c] += f.viscous + f.coulomb * (sech * sech / f.velocity_scale);
  }
  for (int l = 0; l < dynamics_.latch_count(); ++l) {
    if (!dynamics_.latch_state().engaged(l)) continue;
    const Latch& latch = scene.latches[l];
    stiffness_[model.coordinate[latch.joint]] += latch.stiffness;
    damping_[model.coordinate[latch.joint]] += latch.damping;
  }
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
  // Springs and latches act on one-coordinate joints only (the first n1
  // entries of q and p alike); a ball or free joint's positions follow its
  // rates through q' = N(q) w.
  const Model& model = dynamics_.model();
  const int n1 = model.scalar_coordinates;
  for (int c = 0; c < L.nv; ++c) r_[c] = rp[c] - (c < n1 ? gamma * stiffness_[c] * rq[c] : 0.0);
  Eigen::Map<const Eigen::VectorXd> r_map(r_.data(), L.nv);
  Eigen::Map<Eigen::VectorXd> x_map(x_.data(), L.nv);
  sweep_.bias_pass(r_map, phi_);
  sweep_.velocity_pass(r_map, phi_, Vec6::Zero(), x_map, v_);
  // zq = rq + gamma q'(x), zp = rp - gamma (K zq + D x) (no K or D past n1).
  position_rates(model, q_.data(), x_.data(), zq);
  for (int c = 0; c < L.nq; ++c) zq[c] = rq[c] + gamma * zq[c];
  for (int c = 0; c < L.nv; ++c) zp[c] = rp[c] - (c < n1 ? gamma * (stiffness_[c] * zq[c] + damping_[c] * x_[c]) : 0.0);
  Regulator* regulator = dynamics_.regulator();
  if (!regulator) return;
  const RegulatorSettings& s = regulator->settings();
  const double k_pi = s.k_pi(), k_v = s.k_v();  // (16)
  // J (k_pi zq + k_v x) by one kinematic pass: J is linear in the rates.
  for (int c = 0; c < L.nv; ++c) rates_[c] = (c < n1 ? k_pi * zq[c] : k_pi * gamma * x_[c]) + k_v * x_[c];
  sweep_.velocities_from_rates(rates_.data(), v_);
  regulator->residual_rate(v_, g_dot_.data());
  for (int c = 0; c < L.m; ++c) z[L.u() + c] = r[L.u() + c] + gamma * g_dot_[c];
}

}  // namespace unfurl
