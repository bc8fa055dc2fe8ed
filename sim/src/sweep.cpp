#include "unfurl/sim/sweep.hpp"

#include <Eigen/Cholesky>
#include <algorithm>

namespace unfurl::sim {

Sweep::Sweep(const Model& model)
    : model_(model),
      A_(model.size()),
      M_(model.size()),
      X_(model.size()),
      M_star_(model.size()),
      M_star_A_(model.size()),
      D_(model.size(), 0.0),
      multi_(model.size(), -1),
      driven_(model.size(), 0),
      q_(model.nq, 0.0) {
  for (int i = 0; i < model.size(); ++i) {
    A_[i] = model.joints[i].motion_axis();
    M_[i] = model.bodies[i].spatial_mass();
    driven_[i] = model.joints[i].driven && model.joints[i].is_scalar();
    if (model.joints[i].dof() > 1) {
      multi_[i] = static_cast<int>(multi_axes_.size());
      multi_axes_.push_back({model.joints[i].motion_axes(q_.data() + std::max(0, model.first_position[i].value)),
                             Mat6::Zero(), Mat6::Zero(), model.joints[i].dof(), model.joints[i].has_varying_axes()});
    }
  }
}

// D_i = (A_i^T M*_i A_i + diag k)^-1 of order n_i by its Cholesky factor;
// the padding is made the identity for the factorization and zero after.
void Sweep::factor_multi_axis(int i, const double* joint_diagonal) {
  MultiAxis& J = multi_axes_[multi_[i]];
  const int c = model_.first_velocity[i].value;
  if (J.varying) J.A = model_.joints[i].motion_axes(q_.data() + model_.first_position[i].value);
  J.M_star_A.noalias() = M_star_[i] * J.A;
  Mat6 K = J.A.transpose() * J.M_star_A;
  for (int r = 0; r < 6; ++r) K(r, r) += r < J.n ? (joint_diagonal ? joint_diagonal[c + r] : 0.0) : 1.0;
  J.D = Eigen::LLT<Mat6>(K).solve(Mat6::Identity());
  J.D.bottomRows(6 - J.n).setZero();
  J.D.rightCols(6 - J.n).setZero();
}

void Sweep::set_configuration(const double* q, const double* joint_diagonal) {
  std::copy(q, q + model_.nq, q_.begin());
  const int N = model_.size();
  for (int i = 0; i < N; ++i) {
    const int c = model_.first_position[i].value;
    X_[i] = model_.joints[i].placement(c >= 0 ? q + c : nullptr);
    M_star_[i] = M_[i];
  }
  for (int i = N - 1; i >= 0; --i) {
    Mat6 HM = M_star_[i];  // H_i M*_i
    if (multi_[i] >= 0) {
      factor_multi_axis(i, joint_diagonal);
      const MultiAxis& J = multi_axes_[multi_[i]];
      HM.noalias() -= J.M_star_A * J.D * J.M_star_A.transpose();
    } else if (const int c = model_.first_velocity[i].value; c >= 0) {
      M_star_A_[i] = M_star_[i] * A_[i];
      D_[i] = driven_[i] ? 0.0 : 1.0 / (A_[i].dot(M_star_A_[i]) + (joint_diagonal ? joint_diagonal[c] : 0.0));
      HM.noalias() -= D_[i] * M_star_A_[i] * M_star_A_[i].transpose();
    }
    const int k = model_.parent[i];
    if (k != kBase) M_star_[k] += X_[i].congruence(HM);
  }
}

double Sweep::articulated_inertia(int i, int r) const {
  if (driven_[i]) return A_[i].dot(M_star_A_[i]);  // what the driver moves against
  if (multi_[i] < 0) return 1.0 / D_[i];
  const MultiAxis& J = multi_axes_[multi_[i]];
  return J.A.col(r).dot(M_star_[i] * J.A.col(r));
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
    if (multi_[i] >= 0)
      v[i] += multi_axes_[multi_[i]].A * rates_of(i, dq);
    else if (const int c = model_.first_velocity[i].value; c >= 0)
      v[i] += A_[i] * dq[c];
  }
}

Vec6 Sweep::rates_of(int i, const double* x) const {
  Vec6 w = Vec6::Zero();
  for (int r = 0; r < model_.joints[i].dof(); ++r) w[r] = x[model_.first_velocity[i].value + r];
  return w;
}

void Sweep::accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F, const double* Q,
                          std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq, const double* driven) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) bias[i] = omega_times(v[i], M_[i] * v[i]) - F[i];
  // Backward: a_i holds the velocity-product acceleration c_i = v_i x (A_i
  // dq_i) and ddq the joint's unbalanced force u_i = Q_i - A_i^T p^A_i until
  // the forward pass.
  for (int i = N - 1; i >= 0; --i) {
    const int c = model_.first_velocity[i].value;
    a[i].setZero();
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      a[i] = motion_cross(v[i], J.A * rates_of(i, dq));
      if (J.varying)
        a[i] += model_.joints[i].motion_axes_rate(q_.data() + model_.first_position[i].value, dq + c) * rates_of(i, dq);
      const Vec6 u = rates_of(i, Q) - J.A.transpose() * bias[i];
      for (int r = 0; r < J.n; ++r) ddq[c + r] = u[r];
    } else if (driven_[i]) {
      a[i] = motion_cross(v[i], A_[i] * dq[c]);
      ddq[c] = driven ? driven[c] : 0.0;
    } else if (c >= 0) {
      a[i] = motion_cross(v[i], A_[i] * dq[c]);
      ddq[c] = Q[c] - A_[i].dot(bias[i]);
    }
    const int k = model_.parent[i];
    if (k == kBase) continue;
    // p^a = p^A + I^a c + M*A D u with I^a = H_i M*_i = M* - M*A D (M*A)^T.
    Vec6 carried = bias[i] + M_star_[i] * a[i];
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      carried += J.M_star_A * (J.D * (rates_of(i, ddq) - J.M_star_A.transpose() * a[i]));
    } else if (driven_[i]) {
      carried += M_star_A_[i] * ddq[c];  // the given acceleration's
    } else if (c >= 0) {
      carried += M_star_A_[i] * (D_[i] * (ddq[c] - M_star_A_[i].dot(a[i])));
    }
    bias[k] += X_[i].transform_force(carried);
  }
  for (int i = 0; i < N; ++i) {
    const int k = model_.parent[i];
    if (k != kBase) a[i] += X_[i].transform_velocity(a[k]);
    const int c = model_.first_velocity[i].value;
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      const Vec6 ddq_i = J.D * (rates_of(i, ddq) - J.M_star_A.transpose() * a[i]);
      for (int r = 0; r < J.n; ++r) ddq[c + r] = ddq_i[r];
      a[i] += J.A * ddq_i;
    } else if (c >= 0) {
      if (!driven_[i]) ddq[c] = D_[i] * (ddq[c] - M_star_A_[i].dot(a[i]));
      a[i] += A_[i] * ddq[c];
    }
  }
}

void Sweep::momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi, std::vector<Vec6>& mu) const {
  for (int i = 0; i < model_.size(); ++i) mu[i].noalias() = M_star_[i] * v[i] + phi[i];
}

void Sweep::gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, const double* w, double* dp) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int c = model_.first_velocity[i].value;
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      Vec6 dp_i = -J.A.transpose() * omega_times(v[i], mu[i]);
      if (J.varying)
        dp_i +=
            model_.joints[i].motion_axes_rate(q_.data() + model_.first_position[i].value, w + c).transpose() * mu[i];
      for (int r = 0; r < J.n; ++r) dp[c + r] = dp_i[r];
    } else if (c >= 0) {
      dp[c] = -A_[i].dot(omega_times(v[i], mu[i]));
    }
  }
}

}  // namespace unfurl::sim
