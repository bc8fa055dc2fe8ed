// The O(N) sweep of section 4: solves (6) for the joint rates dq, the body
// velocities v and the subtree momenta mu from (q, p), and forms dp of (7).
// Every pass visits each body once; only the n_i x n_i D_i is inverted (a
// division for the one-coordinate joints, a fixed-size Cholesky factor for
// ball, planar and free joints). All storage is allocated by the
// constructor.
//
// Coordinate arrays p, dq, Q and joint_diagonal are per velocity coordinate
// (Model::first_velocity, nv of them); only set_configuration's q is per
// position (Model::first_position, nq).
//
// The passes also run on k load cases at once (6 x k blocks per body, k x
// columns of coordinates), which the loop regulator uses to form W.
//
// A driven joint (Joint::driven) has its rate and acceleration given: it
// passes its whole articulated inertia to its parent, as a locked joint
// does, and its rate's momentum with it (the hybrid form of the
// recursion, as in Featherstone's Rigid Body Dynamics Algorithms, ch. 9).
// Its entry of p is not read; the single-column passes (the state's) take
// its rate from `driven` (per velocity coordinate), and the load cases
// pass none: they see the driven joints locked, as the motor holds them.
#pragma once

#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/model.hpp"
#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

class Sweep {
 public:
  explicit Sweep(const Model& model);

  // Joint placements X_i = (G_i, rho_i) and the articulated quantities
  // M*_i, D_i, M*_i A_i of the first backward pass (they depend on q only).
  // With joint_diagonal (one value per velocity coordinate, k_c), the passes
  // solve with Mtilde + diag(k) instead: D_i = (A_i^T M*_i A_i + k_i)^-1, as
  // a joint's armature enters the articulated inertia. Always computes: what
  // may be reused between calls is the caller's to key (dynamics.hpp).
  void set_configuration(const double* q, const double* joint_diagonal = nullptr);

  // phi*_i of the first backward pass for momenta p (v*_i = 0).
  void bias(const double* p, std::vector<Vec6>& phi, const double* driven = nullptr) const {
    bias_pass(coordinates(p), phi, driven);
  }

  // The forward pass: dq_i and v_i from p, phi* and the base velocity.
  void velocities(const double* p, const std::vector<Vec6>& phi, const Vec6& v_base, double* dq, std::vector<Vec6>& v,
                  const double* driven = nullptr) const {
    auto dq_ = coordinates(dq);
    velocity_pass(coordinates(p), phi, v_base, dq_, v, driven);
  }

  // mu_i = M*_i v_i + phi*_i.
  void momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi, std::vector<Vec6>& mu) const;

  // F*_i = F_i + sum_{j in U_i} C_j^T F*_j in place, and Q_i = A_i^T F*_i,
  // i.e. Q = A^T T^T F.
  void generalized_forces(std::vector<Vec6>& F, double* Q) const {
    auto Q_ = coordinates(Q);
    force_pass(F, Q_);
  }

  // Body poses in the base frame from the placements of the last
  // set_configuration (no trigonometry again).
  void poses(std::vector<Pose>& poses) const;

  // v_i = C_i v_{k_i} + A_i dq_i of (1) for given joint rates dq and a base
  // at rest: the kinematic map, linear in dq.
  void velocities_from_rates(const double* dq, std::vector<Vec6>& v) const;

  // The accelerations: a_i, the rate of v_i in its own frame, and ddq, for
  // joint rates dq, body velocities v, applied body forces F (at the
  // origins, body frames, loop forces included) and joint forces Q. The
  // sweep's M*_i, D_i are the articulated inertias, so this is the sweep
  // carried one derivative further (the articulated-body recursion): a
  // backward pass of the bias forces p^A_i = v_i x* M_i v_i - F_i + what the
  // children pass on, and a forward pass. With them, M*_i a_i + p^A_i is the
  // wrench that joint i transmits from the parent to body i (at its origin,
  // in its frame). The base moves steadily (its acceleration is zero). A
  // driven joint's acceleration is `driven`'s entry (zero where null).
  void accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F, const double* Q,
                     std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq, const double* driven = nullptr) const;

  // M*_i a_i + p^A_i: the joint wrench from accelerations() results.
  Vec6 joint_wrench(int i, const std::vector<Vec6>& bias, const std::vector<Vec6>& a) const {
    return M_star_[i] * a[i] + bias[i];
  }

  // dp_i = (dA_i^T - A_i^T Omega_i) mu_i, the velocity-dependent part of
  // (7); dA_i = 0 but for a universal joint (its rates from w).
  void gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, const double* w, double* dp) const;

  // The same three passes for k load cases: S[i] is 6 x k, P is nq x k.
  template <class S, class P>
  void bias_pass(const P& p, std::vector<S>& phi, const double* driven = nullptr) const;
  template <class S, class P, class Pout>
  void velocity_pass(const P& p, const std::vector<S>& phi, const Vec6& v_base, Pout& dq, std::vector<S>& v,
                     const double* driven = nullptr) const;
  template <class S, class Pout>
  void force_pass(std::vector<S>& F, Pout& Q) const;

  const Placement& placement(int i) const { return X_[i]; }
  // The articulated inertia of joint i's coordinate r, (D_i^-1)_rr: the
  // inertia it moves against with every other joint free but the driven
  // ones (kg m^2 for a turn, kg for a slide); a driven joint's is A_i^T M*_i
  // A_i, what its driver moves.
  double articulated_inertia(int i, int r = 0) const;
  // A_i at the configuration, 6 x n_i in the leading columns.
  Mat6 motion_axes(int i) const {
    return multi_[i] >= 0 ? multi_axes_[multi_[i]].A : model_.joints[i].motion_axes();
  }
  const Model& model() const { return model_; }

 private:
  Eigen::Map<Eigen::VectorXd> coordinates(double* x) const { return {x, model_.nv}; }
  Eigen::Map<const Eigen::VectorXd> coordinates(const double* x) const { return {x, model_.nv}; }

  // A joint of n_i > 1 coordinates: A_i, M*_i A_i and D_i padded to 6 x 6
  // with zeros (so the passes stay fixed-size and allocation-free; the
  // padding contributes nothing).
  struct MultiAxis {
    Mat6 A, M_star_A, D;
    int n = 0;
    bool varying = false;  // A depends on q (a universal joint)
  };
  // A 6 x k block whose first n rows are rows c.. of x, the rest zero.
  template <class P>
  static Eigen::Matrix<double, 6, P::ColsAtCompileTime, 0, 6, P::MaxColsAtCompileTime> padded(const P& x, int c,
                                                                                                int n) {
    Eigen::Matrix<double, 6, P::ColsAtCompileTime, 0, 6, P::MaxColsAtCompileTime> out(6, x.cols());
    out.setZero();
    out.topRows(n) = x.middleRows(c, n);
    return out;
  }
  void factor_multi_axis(int i, const double* joint_diagonal);
  // Joint i's entries of a per-velocity-coordinate array, padded to 6.
  Vec6 rates_of(int i, const double* x) const;

  const Model& model_;
  std::vector<Vec6> A_;         // A_i (constant), one-coordinate joints
  std::vector<Mat6> M_;         // M_i (constant)
  std::vector<Placement> X_;    // G_i, rho_i
  std::vector<Mat6> M_star_;    // M*_i
  std::vector<Vec6> M_star_A_;  // M*_i A_i
  std::vector<double> D_;       // D_i = (A_i^T M*_i A_i)^-1; 0 for a driven joint
  std::vector<int> multi_;      // index into multi_axes_, -1 for n_i <= 1
  std::vector<char> driven_;    // Joint::driven
  std::vector<MultiAxis> multi_axes_;
  std::vector<double> q_;  // the q of the quantities above
};

template <class S, class P>
void Sweep::bias_pass(const P& p, std::vector<S>& phi, const double* driven) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) phi[i].setZero();
  for (int j = N - 1; j >= 0; --j) {
    const int k = model_.parent[j];
    if (k == kBase) continue;
    // M*_j A_j D_j p_j + H_j phi*_j
    S carried = phi[j];
    const int c = model_.first_velocity[j].value;
    if (multi_[j] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[j]];
      carried.noalias() += J.M_star_A * (J.D * (padded(p, c, J.n) - J.A.transpose() * phi[j]));
    } else if (driven_[j]) {
      if (driven) carried.col(0) += M_star_A_[j] * driven[c];
    } else if (c >= 0) {
      carried.noalias() += M_star_A_[j] * (D_[j] * (p.row(c) - A_[j].transpose() * phi[j]));
    }
    phi[k] += X_[j].transform_force(carried);
  }
}

template <class S, class P, class Pout>
void Sweep::velocity_pass(const P& p, const std::vector<S>& phi, const Vec6& v_base, Pout& dq, std::vector<S>& v,
                          const double* driven) const {
  const int N = model_.size();
  const S base = v_base.replicate(1, phi.empty() ? 1 : phi[0].cols());
  for (int i = 0; i < N; ++i) {
    const int k = model_.parent[i];
    v[i] = X_[i].transform_velocity(k == kBase ? base : v[k]);
    const int c = model_.first_velocity[i].value;
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      const auto w = (J.D * (padded(p, c, J.n) - J.A.transpose() * (phi[i] + M_star_[i] * v[i]))).eval();
      dq.middleRows(c, J.n) = w.topRows(J.n);
      v[i].noalias() += J.A * w;
    } else if (driven_[i]) {
      dq.row(c).setConstant(driven ? driven[c] : 0.0);
      v[i].noalias() += A_[i] * dq.row(c);
    } else if (c >= 0) {
      dq.row(c) = D_[i] * (p.row(c) - A_[i].transpose() * (phi[i] + M_star_[i] * v[i]));
      v[i].noalias() += A_[i] * dq.row(c);
    }
  }
}

template <class S, class Pout>
void Sweep::force_pass(std::vector<S>& F, Pout& Q) const {
  for (int i = model_.size() - 1; i >= 0; --i) {
    const int c = model_.first_velocity[i].value;
    if (multi_[i] >= 0) {
      const MultiAxis& J = multi_axes_[multi_[i]];
      const auto Q_i = (J.A.transpose() * F[i]).eval();
      Q.middleRows(c, J.n) = Q_i.topRows(J.n);
    } else if (c >= 0) {
      Q.row(c).noalias() = A_[i].transpose() * F[i];
    }
    const int k = model_.parent[i];
    if (k != kBase) F[k] += X_[i].transform_force(F[i]);
  }
}

}  // namespace unfurl::sim
