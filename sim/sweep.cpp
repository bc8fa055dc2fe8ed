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

void Sweep::set_configuration(const double* q) {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) {
    const int c = model_.coordinate[i];
    X_[i] = model_.joints[i].placement(c >= 0 ? q[c] : 0.0);
    M_star_[i] = M_[i];
  }
  for (int i = N - 1; i >= 0; --i) {
    Mat6 HM = M_star_[i];  // H_i M*_i
    if (model_.coordinate[i] >= 0) {
      M_star_A_[i] = M_star_[i] * A_[i];
      D_[i] = 1.0 / A_[i].dot(M_star_A_[i]);
      HM.noalias() -= D_[i] * M_star_A_[i] * M_star_A_[i].transpose();
    }
    const int k = model_.parent[i];
    if (k != kBase) {
      const Mat6 C = X_[i].C();
      M_star_[k].noalias() += C.transpose() * HM * C;
    }
  }
}

void Sweep::bias(const double* p, std::vector<Vec6>& phi) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) phi[i].setZero();
  for (int j = N - 1; j >= 0; --j) {
    const int k = model_.parent[j];
    if (k == kBase) continue;
    // M*_j A_j D_j p_j + H_j phi*_j
    Vec6 carried = phi[j];
    const int c = model_.coordinate[j];
    if (c >= 0) carried += M_star_A_[j] * (D_[j] * (p[c] - A_[j].dot(phi[j])));
    phi[k] += X_[j].transform_force(carried);
  }
}

void Sweep::velocities(const double* p, const std::vector<Vec6>& phi, const Vec6& v_base,
                       double* dq, std::vector<Vec6>& v) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) {
    const int k = model_.parent[i];
    const Vec6 Cv = X_[i].transform_velocity(k == kBase ? v_base : v[k]);
    const int c = model_.coordinate[i];
    if (c >= 0) {
      dq[c] = D_[i] * (p[c] - A_[i].dot(phi[i] + M_star_[i] * Cv));
      v[i] = Cv + A_[i] * dq[c];
    } else {
      v[i] = Cv;
    }
  }
}

void Sweep::momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi,
                    std::vector<Vec6>& mu) const {
  for (int i = 0; i < model_.size(); ++i) mu[i].noalias() = M_star_[i] * v[i] + phi[i];
}

void Sweep::generalized_forces(std::vector<Vec6>& F, double* Q) const {
  for (int i = model_.size() - 1; i >= 0; --i) {
    const int c = model_.coordinate[i];
    if (c >= 0) Q[c] = A_[i].dot(F[i]);
    const int k = model_.parent[i];
    if (k != kBase) F[k] += X_[i].transform_force(F[i]);
  }
}

void Sweep::gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, double* dp) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int c = model_.coordinate[i];
    if (c >= 0) dp[c] = -A_[i].dot(omega_times(v[i], mu[i]));
  }
}

}  // namespace unfurl
