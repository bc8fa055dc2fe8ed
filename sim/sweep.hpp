// The O(N) sweep of section 4: solves (6) for the joint rates dq, the body
// velocities v and the subtree momenta mu from (q, p), and forms dp of (7).
// Every pass visits each body once; only the n_i x n_i (here scalar) D_i is
// inverted. All storage is allocated by the constructor.
#pragma once

#include <vector>

#include "model.hpp"
#include "spatial.hpp"

namespace unfurl {

class Sweep {
 public:
  explicit Sweep(const Model& model);

  // Joint placements X_i = (G_i, rho_i) and the articulated quantities
  // M*_i, D_i, M*_i A_i of the first backward pass (they depend on q only).
  void set_configuration(const double* q);

  // phi*_i of the first backward pass for momenta p (v*_i = 0).
  void bias(const double* p, std::vector<Vec6>& phi) const;

  // The forward pass: dq_i and v_i from p, phi* and the base velocity.
  void velocities(const double* p, const std::vector<Vec6>& phi, const Vec6& v_base,
                  double* dq, std::vector<Vec6>& v) const;

  // mu_i = M*_i v_i + phi*_i.
  void momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi,
               std::vector<Vec6>& mu) const;

  // F*_i = F_i + sum_{j in U_i} C_j^T F*_j in place, and Q_i = A_i^T F*_i,
  // i.e. Q = A^T T^T F.
  void generalized_forces(std::vector<Vec6>& F, double* Q) const;

  // dp_i = -A_i^T Omega_i mu_i, the velocity-dependent part of (7).
  void gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, double* dp) const;

  const Placement& placement(int i) const { return X_[i]; }
  const Vec6& motion_axis(int i) const { return A_[i]; }
  const Model& model() const { return model_; }

 private:
  const Model& model_;
  std::vector<Vec6> A_;         // A_i (constant)
  std::vector<Mat6> M_;         // M_i (constant)
  std::vector<Placement> X_;    // G_i, rho_i
  std::vector<Mat6> M_star_;    // M*_i
  std::vector<Vec6> M_star_A_;  // M*_i A_i
  std::vector<double> D_;       // D_i = (A_i^T M*_i A_i)^-1
};

}  // namespace unfurl
