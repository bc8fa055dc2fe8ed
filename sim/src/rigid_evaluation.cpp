// Dynamics evaluated without the regulator, for analyses: the accelerations
// with the rigid model's loop forces, an element's generalized forces, the
// mass matrix, and the loops' gap and its Jacobian (dynamics.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "closure_rank.hpp"
#include "sparse_closure_rank.hpp"
#include "subtree_spans.hpp"
#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim {

namespace {

// A wrench (f, m) at a body's origin in its axes, as the base frame's
// wrench about the base's origin.
Vec6 wrench_in_base(const Pose& X, const Vec6& F) {
  const Vec3 f = X.rotation.transpose() * F.head<3>();
  Vec6 out;
  out << f, X.rotation.transpose() * F.tail<3>() + X.position.cross(f);
  return out;
}

// A body's velocity (v, omega) at its origin in its axes, as the base
// frame's velocity of the point at the base's origin: its dot product
// with wrench_in_base() is the power.
Vec6 twist_in_base(const Pose& X, const Vec6& V) {
  const Vec3 omega = X.rotation.transpose() * V.tail<3>();
  Vec6 out;
  out << X.rotation.transpose() * V.head<3>() - omega.cross(X.position), omega;
  return out;
}

}  // namespace

bool Dynamics::rigid_accelerations(const double* q, const double* w, double* w_dot) {
  configure(q);
  body_velocities(w, true);
  if (elements_need_poses_ || regulator_) sweep_.poses(poses_);
  add_element_forces(q, w);
  if (regulator_) {
    // d: the loops' gap acceleration under every other force; the
    // accelerations pass consumes the forces, so they are added again.
    sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data());
    regulator_->residual_rate(a_, d_.data());
    if (!sparse_closure_rank_) {  // as the loads are assessed (Dynamics::loads)
      closure_rank_->compute(regulator_->mobility(sweep_));
      closure_rank_->rigid_loop_forces(d_.data(), lambda_.data());
    } else if (sparse_closure_rank_->compute(sweep_, true)) {  // nearby states: each starts the next
      sparse_closure_rank_->rigid_loop_forces(d_.data(), lambda_.data());
    } else {
      return false;
    }
    add_element_forces(q, w);
    regulator_->apply(lambda_.data(), F_);
  }
  sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, w_dot);
  for (int c = 0; c < layout_.nv; ++c)
    if (!std::isfinite(w_dot[c])) return false;
  return true;
}

// Q_c = A_i^T F*_i (the force pass, Sweep::generalized_forces) is the
// power of the subtree's wrenches at the velocities that a unit rate of
// coordinate c gives them: with both in the base frame, each wrench on a
// body of joint i's subtree enters by one dot product.
Eigen::MatrixXd Dynamics::element_joint_forces(const std::vector<std::size_t>& elements,
                                               const std::vector<int>& coordinates, const double* q, const double* w) {
  const Model& model = scene_.model;
  place(q);
  body_velocities(w, true);
  sweep_.poses(poses_);
  if (!subtree_spans_) {
    subtree_spans_ = std::make_unique<SubtreeSpans>(model);
    every_body_.resize(model.size());
    std::iota(every_body_.begin(), every_body_.end(), 0);
  }
  const SubtreeSpans& spans = *subtree_spans_;
  std::vector<int> joint_of(coordinates.size());
  std::vector<Vec6> axis(coordinates.size());
  for (std::size_t j = 0; j < coordinates.size(); ++j) {
    const int c = coordinates[j], i = model.joint_of_velocity[c];
    joint_of[j] = i;
    axis[j] = twist_in_base(poses_[i], sweep_.motion_axes(i).col(c - model.first_velocity[i].value));
  }
  const auto moves = [&](int b) {
    return std::any_of(joint_of.begin(), joint_of.end(), [&](int i) { return spans.contains(i, b); });
  };
  Eigen::VectorXd direct = Eigen::VectorXd::Zero(model.nv);  // what elements put on coordinates themselves
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(elements.size()),
                                            static_cast<Eigen::Index>(coordinates.size()));
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ForceElement& element = *scene_.elements[elements[e]];
    const std::optional<std::vector<int>> listed = element.bodies();
    // An element that lists its bodies reaches a joint only through their
    // wrenches (force_element.hpp): none below the joints, no force.
    if (listed && !listed->empty() && std::none_of(listed->begin(), listed->end(), moves)) continue;
    const std::vector<int>& bodies = listed ? *listed : every_body_;
    for (int b : bodies) F_[b].setZero();
    for (int c : coordinates) direct[c] = 0;
    ElementForces out{RatesOut(direct.data()), F_};
    element.add_forces(element_state(elements[e], q, w, poses_, v_, model.base_velocity, &sweep_), out);
    for (int b : bodies) {
      const Vec6 wrench = wrench_in_base(poses_[b], F_[b]);
      for (std::size_t j = 0; j < coordinates.size(); ++j)
        if (spans.contains(joint_of[j], b)) Q(e, j) += axis[j].dot(wrench);
    }
    for (std::size_t j = 0; j < coordinates.size(); ++j) Q(e, j) += direct[coordinates[j]];
  }
  return Q;
}

Eigen::MatrixXd Dynamics::mass_matrix(const double* q) {
  const Model& model = scene_.model;
  const int n = model.nv;
  configure(q);
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c) {
    unit.setZero();
    unit[c] = 1;
    momenta_of_rates(unit.data(), false, M.col(c).data());
  }
  return M;
}

Eigen::VectorXd Dynamics::loop_gap(const double* q) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(layout_.m);
  if (!regulator_) return g;
  configure(q);
  sweep_.poses(poses_);
  regulator_->gap(poses_, g.data());
  for (int c = 0; c < layout_.m; ++c) g[c] /= regulator_->component_scale(c);
  return g;
}

Eigen::MatrixXd Dynamics::loop_jacobian(const double* q) {
  const int n = scene_.model.nv;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(layout_.m, n);
  if (!regulator_) return G;
  configure(q);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c) {
    unit.setZero();
    unit[c] = 1;
    body_velocities(unit.data(), false);
    regulator_->residual_rate(v_, G.col(c).data());
  }
  for (int r = 0; r < layout_.m; ++r) G.row(r) /= regulator_->component_scale(r);
  return G;
}

}  // namespace unfurl::sim
