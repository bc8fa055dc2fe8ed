// Spatial (6-vector) algebra of the method: velocities and forces are stacked
// linear part first, v = (v, w), F = (f, m), all in the body's own frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace unfurl::sim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// The skew matrix a~ with a~ b = a x b.
inline Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

// A joint's placement of the child in the parent: G (parent frame to child
// frame) and rho (child origin in the parent frame).
struct Placement {
  Mat3 G = Mat3::Identity();
  Vec3 rho = Vec3::Zero();

  // C v_parent of (1): the parent's velocity seen at the child origin, in
  // the child frame. Also for 6 x k blocks of velocities.
  template <class V>
  Eigen::Matrix<double, 6, V::ColsAtCompileTime, 0, 6, V::MaxColsAtCompileTime> transform_velocity(
      const Eigen::MatrixBase<V>& v) const {
    Eigen::Matrix<double, 6, V::ColsAtCompileTime, 0, 6, V::MaxColsAtCompileTime> out(6, v.cols());
    out.template topRows<3>().noalias() = G * (v.template topRows<3>() - skew(rho) * v.template bottomRows<3>());
    out.template bottomRows<3>().noalias() = G * v.template bottomRows<3>();
    return out;
  }

  // C^T F_child: a force at the child origin (child frame) moved to the
  // parent origin, in the parent frame. Also for 6 x k blocks.
  template <class F>
  Eigen::Matrix<double, 6, F::ColsAtCompileTime, 0, 6, F::MaxColsAtCompileTime> transform_force(
      const Eigen::MatrixBase<F>& f) const {
    Eigen::Matrix<double, 6, F::ColsAtCompileTime, 0, 6, F::MaxColsAtCompileTime> out(6, f.cols());
    out.template topRows<3>().noalias() = G.transpose() * f.template topRows<3>();
    out.template bottomRows<3>().noalias() = skew(rho) * out.template topRows<3>();
    out.template bottomRows<3>().noalias() += G.transpose() * f.template bottomRows<3>();
    return out;
  }

  // C^T X C for a symmetric 6x6 X (an inertia carried to the parent), by
  // blocks: rotate into the parent's axes, then shift by rho.
  Mat6 congruence(const Mat6& X) const {
    const Mat3 Gt = G.transpose();
    const Mat3 A = Gt * X.topLeftCorner<3, 3>() * G;
    const Mat3 B = Gt * X.topRightCorner<3, 3>() * G;
    const Mat3 D = Gt * X.bottomRightCorner<3, 3>() * G;
    const Mat3 r = skew(rho);
    const Mat3 Ar = A * r;
    Mat6 out;
    out.topLeftCorner<3, 3>() = A;
    out.topRightCorner<3, 3>() = B - Ar;
    out.bottomLeftCorner<3, 3>() = out.topRightCorner<3, 3>().transpose();
    out.bottomRightCorner<3, 3>() = D + r * B - B.transpose() * r - r * Ar;
    return out;
  }
};

// M_i of (6): the spatial mass matrix about the body origin.
inline Mat6 spatial_inertia(double m, const Vec3& c, const Mat3& J_origin) {
  Mat6 M;
  M.topLeftCorner<3, 3>() = m * Mat3::Identity();
  M.topRightCorner<3, 3>() = -m * skew(c);
  M.bottomLeftCorner<3, 3>() = m * skew(c);
  M.bottomRightCorner<3, 3>() = J_origin;
  return M;
}

// The motion cross product m1 x m2 = (w1 x v2 + v1 x w2, w1 x w2): the
// rate at which a motion m2 fixed in a frame moving with m1 changes.
inline Vec6 motion_cross(const Vec6& m1, const Vec6& m2) {
  Vec6 out;
  out.head<3>() = m1.tail<3>().cross(m2.head<3>()) + m1.head<3>().cross(m2.tail<3>());
  out.tail<3>() = m1.tail<3>().cross(m2.tail<3>());
  return out;
}

// Omega_i mu_i of (7) for v = (v, w) and mu = (h, L).
inline Vec6 omega_times(const Vec6& v, const Vec6& mu) {
  Vec6 out;
  out.head<3>() = v.tail<3>().cross(mu.head<3>());
  out.tail<3>() = v.head<3>().cross(mu.head<3>()) + v.tail<3>().cross(mu.tail<3>());
  return out;
}

}  // namespace unfurl::sim
