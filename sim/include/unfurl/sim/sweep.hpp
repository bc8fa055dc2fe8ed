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
//
// A flexible body (docs/FLEXIBLE.md) is a body of 6 + m velocities: its
// frame's and its elastic rates eta'. Its own joint then has the joint's
// n_i coordinates (none when driven) and the m elastic ones; its articulated inertia M*^ is
// (6 + m) square, and its parent sees the frame's 6 x 6 block of H M*^ as
// from any body. A child of a flexible body hangs on a node frame that the
// modes move (flexible::NodeFrame): it is carried to the body's extended
// velocity by N_a = [C_node, A L]. Rigid bodies keep their passes as they
// were, operation for operation.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "unfurl/sim/flexible/node_frame.hpp"
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
  // Only the placements X_i, the node frames of flexible bodies and the
  // motion axes at q: what poses(), velocities and force elements read.
  // The articulated quantities are stale until set_configuration; an
  // analysis that needs no accelerations saves their O(N) 6 x 6 products.
  void set_placements(const double* q);

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

  // mu_i = M*_i v_i + phi*_i (a flexible body's: the frame's 6 of M*^ (v_i,
  // eta') + phi*^, with the elastic rates of the last velocity pass).
  void momenta(const std::vector<Vec6>& v, const std::vector<Vec6>& phi, std::vector<Vec6>& mu) const;

  // F*_i = F_i + sum_{j in U_i} C_j^T F*_j in place, and Q_i = A_i^T F*_i,
  // i.e. Q = A^T T^T F.
  void generalized_forces(std::vector<Vec6>& F, double* Q) const {
    auto Q_ = coordinates(Q);
    force_pass(F, Q_);
  }
  // The same where F is zero but on `bodies`' root paths: `bodies` lists
  // that union of paths in decreasing order, and Q is written on its
  // bodies' coordinates alone (the rest of Q would be zero). O(its length).
  void generalized_forces_along(const std::vector<int>& bodies, std::vector<Vec6>& F, double* Q) const {
    auto Q_ = coordinates(Q);
    for (const int i : bodies)
      if (flex_[i] >= 0) flexible_[flex_[i]].F.setZero(flexible_[flex_[i]].d, 1);
    for (const int i : bodies) force_step(i, F, Q_);
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

  // M*_i a_i + p^A_i: the joint wrench from accelerations() results (a
  // flexible body's: the frame's 6 of M*^ a^ + p^A^, kept by the pass).
  Vec6 joint_wrench(int i, const std::vector<Vec6>& bias, const std::vector<Vec6>& a) const {
    if (flex_[i] >= 0) return flexible_[flex_[i]].wrench;
    return M_star_[i] * a[i] + bias[i];
  }

  // dp_i = (dA_i^T - A_i^T Omega_i) mu_i, the velocity-dependent part of
  // (7); dA_i = 0 but for a universal joint (its rates from w). A flexible
  // body's elastic momenta get dT/d eta: its own kinetic energy's and its
  // nodes' (NodeFrame::kinetic_gradient).
  void gyroscopic(const std::vector<Vec6>& v, const std::vector<Vec6>& mu, const double* w, double* dp) const;

  // The same three passes for k load cases: S[i] is 6 x k, P is nq x k.
  template <class S, class P>
  void bias_pass(const P& p, std::vector<S>& phi, const double* driven = nullptr) const;
  template <class S, class P, class Pout>
  void velocity_pass(const P& p, const std::vector<S>& phi, const Vec6& v_base, Pout& dq, std::vector<S>& v,
                     const double* driven = nullptr) const;
  template <class S, class Pout>
  void force_pass(std::vector<S>& F, Pout& Q) const;
  // Body i's part of force_pass: its coordinates' Q, its F* on to its parent.
  template <class S, class Pout>
  void force_step(int i, std::vector<S>& F, Pout& Q) const;

  // Joint i's placement from its parent's frame, or, for a child of a
  // flexible body, from the node frame it hangs on.
  const Placement& placement(int i) const { return X_[i]; }
  // Body i's own momentum at its frame's velocity v and the rates w: M_i v,
  // or for a flexible body M^ (v, eta') (6 + m entries: the frame's, then
  // the elastic momenta's own part).
  flexible::ExtendedVector own_momentum(int i, const Vec6& v, const double* w) const;
  // Body i's centre of mass in its frame: a flexible body's as deformed.
  Vec3 centre_of_mass(int i) const;
  // The velocity of the node frame joint i hangs on (flexible parent),
  // from the bodies' velocities v and the rates w.
  Vec6 node_velocity(int i, const std::vector<Vec6>& v, const double* w) const {
    return parent_velocity(i, v, Eigen::Map<const Eigen::VectorXd>(w, model_.nv));
  }
  // Node a of flexible body i: its frame's placement in the body frame (the
  // deformed node), and its velocity and acceleration in its own axes from
  // the bodies' velocities v and the rates w (the acceleration after
  // accelerations()).
  const Placement& node_placement(int i, int a) const { return flexible_[flex_[i]].nodes[a].placement(); }
  Vec6 node_frame_velocity(int i, int a, const std::vector<Vec6>& v, const double* w) const;
  Vec6 node_frame_acceleration(int i, int a, const std::vector<Vec6>& v, const double* w) const;
  // A wrench at node a's frame (its axes, about its origin) as body i's
  // extended force N_a^T f: the frame's wrench, then the elastic
  // coordinates' forces (6 + m entries).
  flexible::ExtendedVector node_force(int i, int a, const Vec6& f) const {
    return flexible_[flex_[i]].N[a].transpose() * f;
  }
  // Flexible body i's N_a = [C_node, A L] (6 x (6 + m)): its extended
  // velocity to node a's frame velocity, and its own mass matrix M^ at its
  // eta ((6 + m) square), both as of the last set_placements.
  const flexible::NodeMatrix& node_matrix(int i, int a) const { return flexible_[flex_[i]].N[a]; }
  const flexible::ExtendedMatrix& flexible_mass(int i) const { return flexible_[flex_[i]].M_own; }
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

  // A flexible body's extended quantities: d = 6 + m; the free axes of its
  // joint in the extended space (the joint's n_i unless driven, then
  // eta's); a driven hinge's axis. phi, F and eta_dot are the passes' scratch.
  // All in place (fixed-size storage): the right-hand side allocates
  // nothing; the passes' scratch holds up to kMaxExtended load cases.
  struct Flexible {
    int body = -1, m = 0, d = 6;
    int joint_free = 0;  // n_i, or 0 for a driven joint
    bool driven = false;
    flexible::ExtendedMatrix M_star, A_free, D, M_star_A;
    flexible::ExtendedVector A_driven;
    std::vector<flexible::NodeFrame> nodes;
    std::vector<flexible::NodeMatrix> N;     // per node, [C_node, A L]
    flexible::ExtendedMatrix M_own;          // M^(eta), the body's own
    mutable flexible::ExtendedMatrix phi, phi_prime, F;  // d x k
    mutable flexible::ExtendedVector eta_dot;
    // The accelerations pass's: p^A^, the velocity-product acceleration of
    // the hinge (and a driven hinge's given one), the free coordinates'
    // unbalanced force, a^, and the joint's wrench.
    mutable flexible::ExtendedVector b, a_c, u, a_hat;
    mutable Vec6 wrench;
  };
  void flexible_accelerations(const std::vector<Vec6>& v, const double* dq, const std::vector<Vec6>& F,
                              const double* Q, std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq,
                              const double* driven) const;
  // A rigid body's joint i in the accelerations pass, shared by both
  // recursions. Backward: a_i the velocity-product acceleration c_i, ddq
  // the unbalanced force u_i (a driven joint's given acceleration); then
  // what body i carries to its parent; forward, once a_i holds the
  // parent's share: ddq_i and a_i.
  void rigid_joint_backward(int i, const std::vector<Vec6>& v, const double* dq, const double* Q,
                            const std::vector<Vec6>& bias, std::vector<Vec6>& a, double* ddq,
                            const double* driven) const;
  Vec6 rigid_carried(int i, const std::vector<Vec6>& bias, const std::vector<Vec6>& a, const double* ddq) const;
  void rigid_joint_forward(int i, std::vector<Vec6>& a, double* ddq) const;
  // A child's carried 6-vector (its frame) into its parent's bias.
  void carry_bias(int j, const Vec6& carried, std::vector<Vec6>& bias) const;
  void configure_flexible(int i, const double* joint_diagonal);
  // Body i's H M* (6 x 6) into its parent's articulated inertia, through
  // the node frame on a flexible parent.
  void carry_inertia(int i, const Mat6& HM);
  void elastic_gyroscopic(int i, const std::vector<Vec6>& v, const std::vector<Vec6>& mu, const double* w,
                          double* dp) const;
  // The velocity of joint i's parent where i hangs: the node frame's on a
  // flexible parent (from its frame's and eta' in dq), the parent's own.
  template <class S, class Pout>
  S parent_velocity(int i, const std::vector<S>& v, const Pout& dq) const;
  // A child's carried wrench (6 x k at its origin, its frame) into its
  // parent's: through the node frame into the extended scratch on a
  // flexible parent.
  template <class S>
  void carry(int j, const S& carried, std::vector<S>& phi) const;
  template <class S, class P>
  void flexible_bias(int j, const P& p, std::vector<S>& phi, const double* driven) const;
  template <class S, class P, class Pout>
  void flexible_velocity(int i, const P& p, Pout& dq, std::vector<S>& v, const double* driven) const;
  // The free coordinates' rows of x: the joint's (if free), then eta's.
  template <class P>
  flexible::ExtendedMatrix free_rows(int i, const P& x) const;
  // The passes' number of load cases k, at most kMaxExtended with flexible
  // bodies (their scratch is in place; a mechanism's loops, the only source
  // of more, are fewer).
  template <class S>
  int load_cases(const std::vector<S>& x) const {
    const int k = x.empty() ? 1 : static_cast<int>(x[0].cols());
    if (k > flexible::kMaxExtended) throw std::logic_error("the sweep's passes take at most 30 load cases with flexible bodies");
    return k;
  }
  // Joint i's entries of a per-velocity-coordinate array, padded to 6.
  Vec6 rates_of(int i, const double* x) const;
  // c_i = v_i x (A_i q'_i) + (dA_i/dt) q'_i: the velocity-product
  // acceleration across joint i (rates dq).
  Vec6 joint_velocity_product(int i, const std::vector<Vec6>& v, const double* dq) const;

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
  std::vector<int> flex_;  // index into flexible_, -1 for a rigid body
  std::vector<Flexible> flexible_;
  std::vector<double> q_;  // the q of the quantities above
};

template <class P>
flexible::ExtendedMatrix Sweep::free_rows(int i, const P& x) const {
  const Flexible& f = flexible_[flex_[i]];
  flexible::ExtendedMatrix out(f.joint_free + f.m, x.cols());
  out.topRows(f.joint_free) = x.middleRows(std::max(0, model_.first_velocity[i].value), f.joint_free);
  out.bottomRows(f.m) = x.middleRows(model_.first_elastic_velocity[i], f.m);
  return out;
}

template <class S, class Pout>
S Sweep::parent_velocity(int i, const std::vector<S>& v, const Pout& dq) const {
  const int k = model_.parent[i], a = model_.node_of(i);
  if (a < 0) return v[k];
  const Flexible& f = flexible_[flex_[k]];
  flexible::ExtendedMatrix hat(f.d, v[k].cols());
  hat.topRows(6) = v[k];
  hat.bottomRows(f.m) = dq.middleRows(model_.first_elastic_velocity[k], f.m);
  return f.N[a] * hat;
}

template <class S>
void Sweep::carry(int j, const S& carried, std::vector<S>& phi) const {
  const int k = model_.parent[j], a = model_.node_of(j);
  if (a < 0) {
    phi[k] += X_[j].transform_force(carried);
    return;
  }
  const Flexible& f = flexible_[flex_[k]];
  f.phi.noalias() += f.N[a].transpose() * X_[j].transform_force(carried);
}

template <class S, class P>
void Sweep::flexible_bias(int j, const P& p, std::vector<S>& phi, const double* driven) const {
  const Flexible& f = flexible_[flex_[j]];
  f.phi.topRows(6) += phi[j];  // what children hung on the frame itself carried
  f.phi_prime = f.phi;
  if (f.driven && driven) f.phi_prime.col(0) += f.M_star * f.A_driven * driven[model_.first_velocity[j].value];
  const flexible::ExtendedMatrix carried =
      f.phi_prime + f.M_star_A * (f.D * (free_rows(j, p) - f.A_free.transpose() * f.phi_prime));
  phi[j] = f.phi.topRows(6);
  if (model_.parent[j] != kBase) carry(j, S(carried.topRows(6)), phi);
}

template <class S, class P, class Pout>
void Sweep::flexible_velocity(int i, const P& p, Pout& dq, std::vector<S>& v, const double* driven) const {
  const Flexible& f = flexible_[flex_[i]];
  const int c = model_.first_velocity[i].value, e = model_.first_elastic_velocity[i];
  flexible::ExtendedMatrix hat = flexible::ExtendedMatrix::Zero(f.d, v[i].cols());
  hat.topRows(6) = v[i];
  const flexible::ExtendedMatrix x = f.D * (free_rows(i, p) - f.A_free.transpose() * (f.phi_prime + f.M_star * hat));
  if (f.driven) {
    dq.row(c).setConstant(driven ? driven[c] : 0.0);
    hat += f.A_driven * dq.row(c);
  } else {
    dq.middleRows(std::max(0, c), f.joint_free) = x.topRows(f.joint_free);
  }
  dq.middleRows(e, f.m) = x.bottomRows(f.m);
  hat.noalias() += f.A_free * x;
  v[i] = hat.topRows(6);
  if (hat.cols() == 1) f.eta_dot = hat.col(0).tail(f.m);
}

template <class S, class P>
void Sweep::bias_pass(const P& p, std::vector<S>& phi, const double* driven) const {
  const int N = model_.size();
  for (int i = 0; i < N; ++i) phi[i].setZero();
  for (const Flexible& f : flexible_) f.phi.setZero(f.d, load_cases(phi));
  for (int j = N - 1; j >= 0; --j) {
    if (flex_[j] >= 0) {
      flexible_bias(j, p, phi, driven);
      continue;
    }
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
    if (model_.node_of(j) >= 0) {
      carry(j, carried, phi);
      continue;
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
    if (model_.node_of(i) >= 0)
      v[i] = X_[i].transform_velocity(parent_velocity(i, v, dq));
    else
      v[i] = X_[i].transform_velocity(k == kBase ? base : v[k]);
    if (flex_[i] >= 0) {
      flexible_velocity(i, p, dq, v, driven);
      continue;
    }
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
  for (const Flexible& f : flexible_) f.F.setZero(f.d, load_cases(F));
  for (int i = model_.size() - 1; i >= 0; --i) force_step(i, F, Q);
}

template <class S, class Pout>
void Sweep::force_step(int i, std::vector<S>& F, Pout& Q) const {
  const int c = model_.first_velocity[i].value;
  if (flex_[i] >= 0) {
    const Flexible& f = flexible_[flex_[i]];
    f.F.topRows(6) += F[i];
    F[i] = f.F.topRows(6);
    Q.middleRows(model_.first_elastic_velocity[i], f.m) = f.F.bottomRows(f.m);
  }
  if (multi_[i] >= 0) {
    const MultiAxis& J = multi_axes_[multi_[i]];
    const auto Q_i = (J.A.transpose() * F[i]).eval();
    Q.middleRows(c, J.n) = Q_i.topRows(J.n);
  } else if (c >= 0) {
    Q.row(c).noalias() = A_[i].transpose() * F[i];
  }
  const int k = model_.parent[i];
  if (k == kBase) return;
  if (const int a = model_.node_of(i); a >= 0) {
    const Flexible& f = flexible_[flex_[k]];
    f.F.noalias() += f.N[a].transpose() * X_[i].transform_force(F[i]);
  } else {
    F[k] += X_[i].transform_force(F[i]);
  }
}

}  // namespace unfurl::sim
