#include "unfurl/sim/flexible/node_frame.hpp"

#include <Eigen/Geometry>

namespace unfurl::sim::flexible {
namespace {

// Virtual joint k's axis in its own frame: slides along x, y, z, then
// turns about x, y, z.
Vec6 axis(int k) {
  Vec6 a = Vec6::Zero();
  a[k] = 1;
  return a;
}

}  // namespace

void NodeFrame::set(const FlexibleNode& node, const double* eta) {
  node_ = &node;
  const int m = static_cast<int>(node.shape.cols());
  Vec6 s = node.shape * Eigen::Map<const Eigen::VectorXd>(eta, m);
  s.head<3>() += node.point;
  for (int k = 0; k < 3; ++k) X_[k] = {Mat3::Identity(), s[k] * Vec3::Unit(k)};
  for (int k = 0; k < 3; ++k)
    X_[3 + k] = {Eigen::AngleAxisd(s[3 + k], Vec3::Unit(k)).toRotationMatrix().transpose(), Vec3::Zero()};
  to_node_ = Placement{};
  for (int k = 0; k < 6; ++k) to_node_ = then(to_node_, X_[k]);
  // Axis k carried through the placements after it.
  for (int k = 0; k < 6; ++k) {
    Vec6 a = axis(k);
    for (int l = k + 1; l < 6; ++l) a = X_[l].transform_velocity(a);
    A_.col(k) = a;
  }
  AL_.noalias() = A_ * node.shape;
}

Vec6 NodeFrame::velocity_product(const Vec6& v, const double* eta_dot) const {
  const int m = static_cast<int>(node_->shape.cols());
  const Vec6 s_dot = node_->shape * Eigen::Map<const Eigen::VectorXd>(eta_dot, m);
  Vec6 v_k = v, c = Vec6::Zero();
  for (int k = 0; k < 6; ++k) {
    v_k = X_[k].transform_velocity(v_k) + axis(k) * s_dot[k];
    c = X_[k].transform_velocity(c) + motion_cross(v_k, axis(k) * s_dot[k]);
  }
  return c;
}

void NodeFrame::add_kinetic_gradient(const Vec6& v, const double* eta_dot, const Vec6& mu,
                                     Eigen::Ref<Eigen::VectorXd> g_eta) const {
  const int m = static_cast<int>(node_->shape.cols());
  const Vec6 s_dot = node_->shape * Eigen::Map<const Eigen::VectorXd>(eta_dot, m);
  std::array<Vec6, 6> v_k;
  Vec6 v_prev = v;
  for (int k = 0; k < 6; ++k) v_prev = v_k[k] = X_[k].transform_velocity(v_prev) + axis(k) * s_dot[k];
  Vec6 g, mu_k = mu;
  for (int k = 5; k >= 0; --k) {
    g[k] = -axis(k).dot(omega_times(v_k[k], mu_k));
    mu_k = X_[k].transform_force(mu_k);
  }
  g_eta.noalias() += node_->shape.transpose() * g;
}

}  // namespace unfurl::sim::flexible
