#include "unfurl/sim/sweep.hpp"

#include <algorithm>

namespace unfurl {

Sweep::Sweep(const Model& model)
    : model_(model),
      A_(model.size()),
      M_(model.size()),
      X_(model.size()),
      M_star_(model.size()),
      M_star_A_(model.size()),
      D_(model.size(), 0.0),
      q_(model.nq, 0.0) {
  for (int i = 0; i < model.size(); ++i) {
    A_[i] = model.joints[i].motion_axis();
    M_[i] = model.bodies[i].spatial_mass();
  }
}

void Sweep::set_configuration(const double* q, const double* joint_diagonal) {
  if (configuration_ > 0 && !joint_diagonal && !with_diagonal_ && std::equal(q_.begin(), q_.end(), q)) return;
  std::copy(q, q + model_.nq, q_.begin());
  with_diagonal_ = joint_diagonal != nullptr;
  ++configuration_;
  const int N = model_.size();
  for (int i = 0; i < N; ++i) {
    const int c = model_.coordinate[i];
    X_[i] = model_.joints[i].placement(c >= 0 ? q[c] : 0.0);
    M_star_[i] = M_[i];
  }
  for (int i = N - 1; i >= 0; --i) {
    Mat6 HM = M_star_[i];  // H_i M*_i
    if (const int c = model_.coordinate[i]; c >= 0) {
      M_star_A_[i] = M_star_[i] * A_[i];
      D_[i] = 1.0 / (A_[i].dot(M_star_A_[i]) + (joint_diagonal ? joint_diagonal[c] : 0.0));
      HM.noalias() -= D_[i] * M_star_A_[i] * M_star_A_[i].transpose();
    }
    const int k = model_.parent[i];
    if (k != kBase) M_star_[k] += X_[i].congruence(HM);
  }
}

void Sweep::poses(std::vector<Pose>& poses) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int k = model_.parent[i];
    poses[i] = (k == kBase ? Pose{} : poses[k]).child(X_[i]);
  }
}

void Sweep::velocities_from_rates(const double* dq, std::vector<Vec6>& v) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int k = model_.parent[i];
    if (k == kBase)
      v[i].setZero();
    else
      v[i] = X_[i].transform_velocity(v[k]);
    if (const int c = model_.coordinate[i]; c >= 0) v[i] += A_[i] * dq[c];
  }
}

void Sweep::accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F, const double* Q,
                          std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) bias[i] = omega_times(v[i], M_[i] * v[i]) - F[i];
  // Backward: a_i holds the velocity-product acceleration c_i = v_i x (A_i
  // dq_i) and ddq the joint's unbalanced force u_i = Q_i - A_i^T p^A_i until
  // the forward pass.
  for (int i = N - 1; i >= 0; --i) {
    const int c = model_.coordinate[i];
    a[i].setZero();
    if (c >= 0) {
      a[i] = motion_cross(v[i], A_[i] * dq[c]);
      ddq[c] = Q[c] - A_[i].dot(bias[i]);
    }
    const int k = model_.parent[i];
    if (k == kBase) continue;
    // p^a = p^A + I^a c + M*A D u with I^a = H_i M*_i = M* - M*A D (M*A)^T.
    Vec6 carried = bias[i] + M_star_[i] * a[i];
    if (c >= 0) carried += M_star_A_[i] * (D_[i] * (ddq[c] - M_star_A_[i].dot(a[i])));
    bias[k] += X_[i].transform_force(carried);
  }
  for (int i = 0; i < N; ++i) {
    const int k = model_.parent[i];
    if (k != kBase) a[i] += X_[i].transform_velocity(a[k]);
    if (const int c = model_.coordinate[i]; c >= 0) {
      ddq[c] = D_[i] * (ddq[c] - M_star_A_[i].dot(a[i]));
      a[i] += A_[i] * ddq[c];
    }
  }
}

void Sweep::momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi, std::vector<Vec6>& mu) const {
  for (int i = 0; i < model_.size(); ++i) mu[i].noalias() = M_star_[i] * v[i] + phi[i];
}

void Sweep::gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, double* dp) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int c = model_.coordinate[i];
    if (c >= 0) dp[c] = -A_[i].dot(omega_times(v[i], mu[i]));
  }
}

}  // namespace unfurl
