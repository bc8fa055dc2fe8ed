#include "newton_preconditioner.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl {

NewtonPreconditioner::NewtonPreconditioner(Dynamics& dynamics)
    : dynamics_(dynamics),
      sweep_(dynamics.model()),
      stiffness_(dynamics.model().nq),
      damping_(dynamics.model().nq),
      diagonal_(dynamics.model().nq),
      r_(dynamics.model().nq),
      x_(dynamics.model().nq),
      rates_(dynamics.model().nq),
      g_dot_(dynamics.layout().m),
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
  for (int c = 0; c < model.nq; ++c) diagonal_[c] = gamma * damping_[c] + gamma * gamma * stiffness_[c];
  sweep_.set_configuration(y + dynamics_.layout().q(), diagonal_.data());
}

void NewtonPreconditioner::solve(const double* r, double* z) {
  const StateLayout& L = dynamics_.layout();
  const double gamma = gamma_;
  const double* rq = r + L.q();
  const double* rp = r + L.p();
  double* zq = z + L.q();
  double* zp = z + L.p();
  // (Mtilde + gamma D + gamma^2 K) x = rp - gamma K rq, then back-substitute.
  for (int c = 0; c < L.nq; ++c) r_[c] = rp[c] - gamma * stiffness_[c] * rq[c];
  Eigen::Map<const Eigen::VectorXd> r_map(r_.data(), L.nq);
  Eigen::Map<Eigen::VectorXd> x_map(x_.data(), L.nq);
  sweep_.bias_pass(r_map, phi_);
  sweep_.velocity_pass(r_map, phi_, Vec6::Zero(), x_map, v_);
  for (int c = 0; c < L.nq; ++c) {
    zq[c] = rq[c] + gamma * x_[c];
    zp[c] = rp[c] - gamma * (stiffness_[c] * zq[c] + damping_[c] * x_[c]);
  }
  Regulator* regulator = dynamics_.regulator();
  if (!regulator) return;
  const RegulatorSettings& s = regulator->settings();
  const double k_pi = s.k_pi(), k_v = s.k_v();  // (16)
  // J (k_pi zq + k_v x) by one kinematic pass: J is linear in the rates.
  for (int c = 0; c < L.nq; ++c) rates_[c] = k_pi * zq[c] + k_v * x_[c];
  sweep_.velocities_from_rates(rates_.data(), v_);
  regulator->residual_rate(v_, g_dot_.data());
  for (int c = 0; c < L.m; ++c) z[L.u() + c] = r[L.u() + c] + gamma * g_dot_[c];
}

}  // namespace unfurl
