// Spatial (6-vector) algebra of the method: velocities and forces are stacked
// linear part first, v = (v, w), F = (f, m), all in the body's own frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace unfurl {

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
  // the child frame.
  Vec6 transform_velocity(const Vec6& v) const {
    Vec6 out;
    out.head<3>() = G * (v.head<3>() + v.tail<3>().cross(rho));
    out.tail<3>() = G * v.tail<3>();
    return out;
  }

  // C^T F_child: a force at the child origin (child frame) moved to the
  // parent origin, in the parent frame.
  Vec6 transform_force(const Vec6& F) const {
    Vec6 out;
    out.head<3>() = G.transpose() * F.head<3>();
    out.tail<3>() = rho.cross(out.head<3>()) + G.transpose() * F.tail<3>();
    return out;
  }

  // C of (1) as a matrix.
  Mat6 C() const {
    Mat6 c;
    c.topLeftCorner<3, 3>() = G;
    c.topRightCorner<3, 3>() = -G * skew(rho);
    c.bottomLeftCorner<3, 3>().setZero();
    c.bottomRightCorner<3, 3>() = G;
    return c;
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

// Omega_i mu_i of (7) for v = (v, w) and mu = (h, L).
inline Vec6 omega_times(const Vec6& v, const Vec6& mu) {
  Vec6 out;
  out.head<3>() = v.tail<3>().cross(mu.head<3>());
  out.tail<3>() = v.head<3>().cross(mu.head<3>()) + v.tail<3>().cross(mu.tail<3>());
  return out;
}

}  // namespace unfurl
