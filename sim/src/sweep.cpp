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
      flex_(model.size(), -1),
      q_(model.nq, 0.0) {
  for (int i = 0; i < model.size(); ++i) {
    A_[i] = model.joints[i].motion_axis();
    M_[i] = model.bodies[i].spatial_mass();
    if (model.flexible(i)) {
      flex_[i] = static_cast<int>(flexible_.size());
      Flexible f;
      f.body = i;
      f.m = model.bodies[i].flexible->modes();
      f.d = 6 + f.m;
      f.driven = model.joints[i].driven;
      f.joint_free = f.driven ? 0 : model.joints[i].dof();
      f.A_free = flexible::ExtendedMatrix::Zero(f.d, f.joint_free + f.m);
      f.A_free.topLeftCorner(6, f.joint_free) = model.joints[i].motion_axes(q_.data()).leftCols(f.joint_free);
      f.A_free.bottomRightCorner(f.m, f.m).setIdentity();
      f.A_driven = flexible::ExtendedVector::Zero(f.d);
      f.M_own.resize(f.d, f.d);
      if (f.driven) f.A_driven.head<6>() = A_[i];
      f.nodes.resize(model.bodies[i].flexible->nodes.size());
      f.N.assign(f.nodes.size(), flexible::NodeMatrix::Zero(6, f.d));
      flexible_.push_back(std::move(f));
    }
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
  J.M_star_A.noalias() = M_star_[i] * J.A;
  Mat6 K = J.A.transpose() * J.M_star_A;
  for (int r = 0; r < 6; ++r) K(r, r) += r < J.n ? (joint_diagonal ? joint_diagonal[c + r] : 0.0) : 1.0;
  J.D = Eigen::LLT<Mat6>(K).solve(Mat6::Identity());
  J.D.bottomRows(6 - J.n).setZero();
  J.D.rightCols(6 - J.n).setZero();
}

// The flexible body's M*^ is complete (its children's are in): D over its
// free coordinates, and H M*^ whose frame block goes to the parent.
void Sweep::configure_flexible(int i, const double* joint_diagonal) {
  Flexible& f = flexible_[flex_[i]];
  flexible::ExtendedMatrix K = f.A_free.transpose() * f.M_star * f.A_free;
  if (joint_diagonal) {
    for (int r = 0; r < f.joint_free; ++r) K(r, r) += joint_diagonal[model_.first_velocity[i].value + r];
    for (int r = 0; r < f.m; ++r) K(f.joint_free + r, f.joint_free + r) += joint_diagonal[model_.first_elastic_velocity[i] + r];
  }
  f.D = Eigen::LLT<flexible::ExtendedMatrix>(K).solve(flexible::ExtendedMatrix::Identity(K.rows(), K.cols()));
  f.M_star_A = f.M_star * f.A_free;
  M_star_[i] = (f.M_star - f.M_star_A * f.D * f.M_star_A.transpose()).topLeftCorner<6, 6>();  // H M*^'s frame block
}

void Sweep::set_placements(const double* q) {
  std::copy(q, q + model_.nq, q_.begin());
  const int N = model_.size();
  for (int i = 0; i < N; ++i) {
    const int c = model_.first_position[i].value;
    X_[i] = model_.joints[i].placement(c >= 0 ? q + c : nullptr);
    M_star_[i] = M_[i];
    if (const int a = model_.node_of(i); a >= 0) X_[i].rho -= model_.bodies[model_.parent[i]].flexible->nodes[a].point;
    if (multi_[i] >= 0 && multi_axes_[multi_[i]].varying) multi_axes_[multi_[i]].A = model_.joints[i].motion_axes(q + c);
    if (flex_[i] < 0) continue;
    Flexible& f = flexible_[flex_[i]];
    if (multi_[i] >= 0 && multi_axes_[multi_[i]].varying)
      f.A_free.topLeftCorner(6, f.joint_free) = multi_axes_[multi_[i]].A.leftCols(f.joint_free);
    const double* eta = q + model_.first_elastic_position[i];
    model_.bodies[i].flexible->inertia.mass_matrix(eta, f.M_own);
    f.M_star = f.M_own;
    for (std::size_t a = 0; a < f.nodes.size(); ++a) {
      f.nodes[a].set(model_.bodies[i].flexible->nodes[a], eta);
      f.N[a] << flexible::velocity_matrix(f.nodes[a].placement()), f.nodes[a].rates();
    }
  }
}

void Sweep::set_configuration(const double* q, const double* joint_diagonal) {
  set_placements(q);
  const int N = model_.size();
  for (int i = N - 1; i >= 0; --i) {
    if (flex_[i] >= 0) {
      configure_flexible(i, joint_diagonal);
      if (const int k = model_.parent[i]; k != kBase) carry_inertia(i, M_star_[i]);
      continue;
    }
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
    if (k != kBase) carry_inertia(i, HM);
  }
  // A flexible body's M_star_ holds its H M*^ frame block, for its parent;
  // its own M*^ is in flexible_.
}

void Sweep::carry_inertia(int i, const Mat6& HM) {
  const int k = model_.parent[i], a = model_.node_of(i);
  if (a < 0) {
    if (flex_[k] >= 0)
      flexible_[flex_[k]].M_star.topLeftCorner<6, 6>() += X_[i].congruence(HM);
    else
      M_star_[k] += X_[i].congruence(HM);
    return;
  }
  Flexible& f = flexible_[flex_[k]];
  const flexible::NodeMatrix T = flexible::velocity_matrix(X_[i]) * f.N[a];
  f.M_star.noalias() += T.transpose() * HM * T;
}

double Sweep::articulated_inertia(int i, int r) const {
  if (flex_[i] >= 0) {
    const Vec6 A = multi_[i] >= 0 ? Vec6(multi_axes_[multi_[i]].A.col(r)) : A_[i];
    return A.dot(flexible_[flex_[i]].M_star.topLeftCorner<6, 6>() * A);
  }
  if (driven_[i]) return A_[i].dot(M_star_A_[i]);  // what the driver moves against
  if (multi_[i] < 0) return 1.0 / D_[i];
  const MultiAxis& J = multi_axes_[multi_[i]];
  return J.A.col(r).dot(M_star_[i] * J.A.col(r));
}

void Sweep::poses(std::vector<Pose>& poses) const {
  for (int i = 0; i < model_.size(); ++i) {
    const int k = model_.parent[i];
    if (const int a = model_.node_of(i); a >= 0)
      poses[i] = poses[k].child(flexible_[flex_[k]].nodes[a].placement()).child(X_[i]);
    else
      poses[i] = (k == kBase ? Pose{} : poses[k]).child(X_[i]);
  }
}

void Sweep::velocities_from_rates(const double* dq, std::vector<Vec6>& v) const {
  const Eigen::Map<const Eigen::VectorXd> rates(dq, model_.nv);
  for (int i = 0; i < model_.size(); ++i) {
    const int k = model_.parent[i];
    if (k == kBase)
      v[i].setZero();
    else if (model_.node_of(i) >= 0)
      v[i] = X_[i].transform_velocity(parent_velocity(i, v, rates));
    else
      v[i] = X_[i].transform_velocity(v[k]);
    if (multi_[i] >= 0)
      v[i] += multi_axes_[multi_[i]].A * rates_of(i, dq);
    else if (const int c = model_.first_velocity[i].value; c >= 0)
      v[i] += A_[i] * dq[c];
  }
}

Vec6 Sweep::joint_velocity_product(int i, const std::vector<Vec6>& v, const double* dq) const {
  if (multi_[i] < 0) return motion_cross(v[i], A_[i] * dq[model_.first_velocity[i].value]);
  const MultiAxis& J = multi_axes_[multi_[i]];
  Vec6 c = motion_cross(v[i], J.A * rates_of(i, dq));
  if (J.varying) c += model_.joints[i].motion_axes_rate(q_.data() + model_.first_position[i].value,
                                                        dq + model_.first_velocity[i].value) * rates_of(i, dq);
  return c;
}

Vec6 Sweep::rates_of(int i, const double* x) const {
  Vec6 w = Vec6::Zero();
  for (int r = 0; r < model_.joints[i].dof(); ++r) w[r] = x[model_.first_velocity[i].value + r];
  return w;
}

flexible::ExtendedVector Sweep::own_momentum(int i, const Vec6& v, const double* w) const {
  if (flex_[i] < 0) return M_[i] * v;
  const Flexible& f = flexible_[flex_[i]];
  flexible::ExtendedVector V(f.d);
  V << v, Eigen::Map<const Eigen::VectorXd>(w + model_.first_elastic_velocity[i], f.m);
  return f.M_own * V;
}

Vec3 Sweep::centre_of_mass(int i) const {
  if (flex_[i] < 0) return model_.bodies[i].com;
  const flexible::ExtendedMatrix& M = flexible_[flex_[i]].M_own;
  const Mat3 mc = M.block<3, 3>(3, 0);  // (m c)~, as the undeformed body's
  return Vec3(mc(2, 1), mc(0, 2), mc(1, 0)) / M(0, 0);
}

Vec6 Sweep::node_frame_velocity(int i, int a, const std::vector<Vec6>& v, const double* w) const {
  const Flexible& f = flexible_[flex_[i]];
  flexible::ExtendedVector hat(f.d);
  hat << v[i], Eigen::Map<const Eigen::VectorXd>(w + model_.first_elastic_velocity[i], f.m);
  return f.N[a] * hat;
}

Vec6 Sweep::node_frame_acceleration(int i, int a, const std::vector<Vec6>& v, const double* w) const {
  const Flexible& f = flexible_[flex_[i]];
  return f.N[a] * f.a_hat + f.nodes[a].velocity_product(v[i], w + model_.first_elastic_velocity[i]);
}

void Sweep::carry_bias(int j, const Vec6& carried, std::vector<Vec6>& bias) const {
  const int k = model_.parent[j], a = model_.node_of(j);
  if (a >= 0) {
    const Flexible& f = flexible_[flex_[k]];
    f.b.noalias() += f.N[a].transpose() * X_[j].transform_force(carried);
  } else {
    bias[k] += X_[j].transform_force(carried);
  }
}

// The articulated-body recursion with flexible bodies (docs/FLEXIBLE.md):
// a flexible body's bias is p^A^ = (dM^/dt) V + (Omega(v) (M^ V)_frame,
// -dT/d eta) - (F, 0), its joint's free coordinates the joint's and eta's;
// a child on a node adds the node frame's velocity product to its own.
void Sweep::flexible_accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F,
                                   const double* Q, std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq,
                                   const double* driven) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) bias[i] = flex_[i] >= 0 ? Vec6(-F[i]) : Vec6(omega_times(v[i], M_[i] * v[i]) - F[i]);
  for (const Flexible& f : flexible_) {
    const int i = f.body, e = model_.first_elastic_velocity[i];
    const double* eta = q_.data() + model_.first_elastic_position[i];
    flexible::ExtendedVector V(f.d);
    V << v[i], Eigen::Map<const Eigen::VectorXd>(dq + e, f.m);
    const flexible::InertiaInvariants& inertia = model_.bodies[i].flexible->inertia;
    const flexible::ExtendedVector MV = f.M_own * V;
    flexible::ExtendedMatrix M_dot(f.d, f.d);
    inertia.mass_matrix_rate(eta, dq + e, M_dot);
    f.b.noalias() = M_dot * V;
    f.b.head<6>() += omega_times(v[i], MV.head<6>());
    flexible::ExtendedVector g(f.m);
    inertia.kinetic_gradient(eta, V.data(), g);
    f.b.tail(f.m) -= g;
  }
  for (int i = N - 1; i >= 0; --i) {
    const int c = model_.first_velocity[i].value, k = model_.parent[i];
    if (flex_[i] >= 0) {
      const Flexible& f = flexible_[flex_[i]];
      f.b.head<6>() += bias[i];
      f.a_c.setZero(f.d);
      if (c >= 0) f.a_c.head<6>() = joint_velocity_product(i, v, dq);
      if (f.driven) f.a_c += f.A_driven * (driven ? driven[c] : 0.0);
      if (const int n = model_.node_of(i); n >= 0)
        f.a_c.head<6>() += X_[i].transform_velocity(
            flexible_[flex_[k]].nodes[n].velocity_product(v[k], dq + model_.first_elastic_velocity[k]));
      flexible::ExtendedVector Q_f(f.joint_free + f.m);
      Q_f.head(f.joint_free) = Eigen::Map<const Eigen::VectorXd>(Q + std::max(0, c), f.joint_free);
      Q_f.tail(f.m) = Eigen::Map<const Eigen::VectorXd>(Q + model_.first_elastic_velocity[i], f.m);
      f.u = Q_f - f.A_free.transpose() * f.b;
      const flexible::ExtendedVector carried =
          f.b + f.M_star * f.a_c + f.M_star_A * (f.D * (f.u - f.M_star_A.transpose() * f.a_c));
      bias[i] = f.b.head<6>();
      if (k != kBase) carry_bias(i, carried.head<6>(), bias);
      continue;
    }
    rigid_joint_backward(i, v, dq, Q, bias, a, ddq, driven);
    if (const int n = model_.node_of(i); n >= 0)
      a[i] += X_[i].transform_velocity(
          flexible_[flex_[k]].nodes[n].velocity_product(v[k], dq + model_.first_elastic_velocity[k]));
    if (k != kBase) carry_bias(i, rigid_carried(i, bias, a, ddq), bias);
  }
  for (int i = 0; i < N; ++i) {
    const int k = model_.parent[i], c = model_.first_velocity[i].value;
    Vec6 from_parent = Vec6::Zero();
    if (k != kBase) {
      if (const int n = model_.node_of(i); n >= 0)
        from_parent = flexible_[flex_[k]].N[n] * flexible_[flex_[k]].a_hat;
      else
        from_parent = a[k];
    }
    if (flex_[i] >= 0) {
      const Flexible& f = flexible_[flex_[i]];
      f.a_hat = f.a_c;
      f.a_hat.head<6>() += X_[i].transform_velocity(from_parent);
      const flexible::ExtendedVector x = f.D * (f.u - f.M_star_A.transpose() * f.a_hat);
      f.a_hat += f.A_free * x;
      if (f.driven) ddq[c] = driven ? driven[c] : 0.0;
      Eigen::Map<Eigen::VectorXd>(ddq + std::max(0, c), f.joint_free) = x.head(f.joint_free);
      Eigen::Map<Eigen::VectorXd>(ddq + model_.first_elastic_velocity[i], f.m) = x.tail(f.m);
      a[i] = f.a_hat.head<6>();
      f.wrench = (f.M_star * f.a_hat + f.b).head<6>();
      continue;
    }
    a[i] += X_[i].transform_velocity(from_parent);
    rigid_joint_forward(i, a, ddq);
  }
}

void Sweep::accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F, const double* Q,
                          std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq, const double* driven) const {
  if (!flexible_.empty()) return flexible_accelerations(v, dq, F, Q, bias, a, ddq, driven);
  const int N = model_.size();
  for (int i = 0; i < N; ++i) bias[i] = omega_times(v[i], M_[i] * v[i]) - F[i];
  // Backward: a_i holds the velocity-product acceleration c_i = v_i x (A_i
  // dq_i) and ddq the joint's unbalanced force u_i = Q_i - A_i^T p^A_i until
  // the forward pass.
  for (int i = N - 1; i >= 0; --i) {
    rigid_joint_backward(i, v, dq, Q, bias, a, ddq, driven);
    if (const int k = model_.parent[i]; k != kBase) bias[k] += X_[i].transform_force(rigid_carried(i, bias, a, ddq));
  }
  for (int i = 0; i < N; ++i) {
    if (const int k = model_.parent[i]; k != kBase) a[i] += X_[i].transform_velocity(a[k]);
    rigid_joint_forward(i, a, ddq);
  }
}

void Sweep::rigid_joint_backward(int i, const std::vector<Vec6>& v, const double* dq, const double* Q,
                                 const std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq,
                                 const double* driven) const {
  const int c = model_.first_velocity[i].value;
  a[i].setZero();
  if (multi_[i] >= 0) {
    const MultiAxis& J = multi_axes_[multi_[i]];
    a[i] = joint_velocity_product(i, v, dq);
    const Vec6 u = rates_of(i, Q) - J.A.transpose() * bias[i];
    for (int r = 0; r < J.n; ++r) ddq[c + r] = u[r];
  } else if (driven_[i]) {
    a[i] = motion_cross(v[i], A_[i] * dq[c]);
    ddq[c] = driven ? driven[c] : 0.0;
  } else if (c >= 0) {
    a[i] = motion_cross(v[i], A_[i] * dq[c]);
    ddq[c] = Q[c] - A_[i].dot(bias[i]);
  }
}

// p^a = p^A + I^a c + M*A D u with I^a = H_i M*_i = M* - M*A D (M*A)^T.
Vec6 Sweep::rigid_carried(int i, const std::vector<Vec6>& bias, const std::vector<Vec6>& a, const double* ddq) const {
  const int c = model_.first_velocity[i].value;
  Vec6 carried = bias[i] + M_star_[i] * a[i];
  if (multi_[i] >= 0) {
    const MultiAxis& J = multi_axes_[multi_[i]];
    carried += J.M_star_A * (J.D * (rates_of(i, ddq) - J.M_star_A.transpose() * a[i]));
  } else if (driven_[i]) {
    carried += M_star_A_[i] * ddq[c];  // the given acceleration's
  } else if (c >= 0) {
    carried += M_star_A_[i] * (D_[i] * (ddq[c] - M_star_A_[i].dot(a[i])));
  }
  return carried;
}

void Sweep::rigid_joint_forward(int i, std::vector<Vec6>& a, double* ddq) const {
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

void Sweep::momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi, std::vector<Vec6>& mu) const {
  for (int i = 0; i < model_.size(); ++i) {
    if (flex_[i] >= 0) {
      const Flexible& f = flexible_[flex_[i]];
      mu[i] = f.M_star.topLeftCorner<6, 6>() * v[i] + f.M_star.topRightCorner(6, f.m) * f.eta_dot + f.phi.col(0).head<6>();
      continue;
    }
    mu[i].noalias() = M_star_[i] * v[i] + phi[i];
  }
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
    if (flex_[i] >= 0) elastic_gyroscopic(i, v, mu, w, dp);
  }
}

// dp_eta = dT/d eta: the body's own kinetic energy's, and what hangs on
// its nodes (the children's subtree momenta carried to each node frame).
void Sweep::elastic_gyroscopic(int i, const std::vector<Vec6>& v, const std::vector<Vec6>& mu, const double* w,
                               double* dp) const {
  const Flexible& f = flexible_[flex_[i]];
  const int e = model_.first_elastic_velocity[i];
  flexible::ExtendedVector V(f.d);
  V << v[i], Eigen::Map<const Eigen::VectorXd>(w + e, f.m);
  flexible::ExtendedVector g(f.m);
  model_.bodies[i].flexible->inertia.kinetic_gradient(q_.data() + model_.first_elastic_position[i], V.data(), g);
  for (std::size_t a = 0; a < f.nodes.size(); ++a) {
    Vec6 hung = Vec6::Zero();
    for (int j : model_.children[i])
      if (model_.node_of(j) == static_cast<int>(a)) hung += X_[j].transform_force(mu[j]);
    f.nodes[a].add_kinetic_gradient(v[i], w + e, hung, g);
  }
  Eigen::Map<Eigen::VectorXd>(dp + e, f.m) = g;
}

}  // namespace unfurl::sim
