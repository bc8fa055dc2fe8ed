#include "sweep.hpp"

namespace unfurl {

Sweep::Sweep(const Model& model)
    : model_(model),
      A_(model.size()),
      M_(model.size()),
      X_(model.size()),
      M_star_(model.size()),
      M_star_A_(model.size()),
      D_(model.size(), 0.0) {
  for (int i = 0; i < model.size(); ++i) {
    A_[i] = model.joints[i].motion_axis();
    M_[i] = model.bodies[i].spatial_mass();
  }
}

void Sweep::set_configuration(const double* q, const double* joint_diagonal) {
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
