#include "unfurl/sim/joint.hpp"

namespace unfurl::sim {

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::revolute: return "revolute";
    case JointType::prismatic: return "prismatic";
    case JointType::fixed: return "fixed";
    case JointType::spherical: return "spherical";
    case JointType::planar: return "planar";
    case JointType::free: return "free";
    case JointType::universal: return "universal";
  }
  return "?";
}

std::optional<JointType> parse_joint_type(const std::string& name) {
  for (JointType type : {JointType::revolute, JointType::prismatic, JointType::fixed, JointType::universal,
                         JointType::spherical, JointType::planar, JointType::free})
    if (name == joint_type_name(type)) return type;
  return std::nullopt;
}

int Joint::dof() const {
  switch (type) {
    case JointType::revolute: return compliant ? 6 : 1;
    case JointType::prismatic: return 1;
    case JointType::fixed: return 0;
    case JointType::universal: return 2;
    case JointType::spherical:
    case JointType::planar: return 3;
    case JointType::free: return 6;
  }
  return 0;
}

int Joint::positions() const {
  switch (type) {
    case JointType::spherical: return 4;
    case JointType::free: return 7;
    default: return dof();
  }
}

Mat3 quaternion_rotation(const double* q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

namespace {

// A compliant hinge's tilts and turn, R = R(e1, r1) R(e2, r2) R(axis, q),
// and the turn alone.
struct CompliantTurn {
  Mat3 R, R_axis;
};

CompliantTurn compliant_turn(const Joint& j, const double* q) {
  CompliantTurn t;
  t.R_axis = Eigen::AngleAxisd(q[0], j.axis).toRotationMatrix();
  t.R = Eigen::AngleAxisd(q[4], j.cross_axis_1()).toRotationMatrix() *
        Eigen::AngleAxisd(q[5], j.cross_axis_2()).toRotationMatrix() * t.R_axis;
  return t;
}

}  // namespace

Placement Joint::placement(const double* q) const {
  Placement P;
  if (compliant) {
    const CompliantTurn t = compliant_turn(*this, q);
    P.G = t.R.transpose();
    P.rho = parent_point + q[1] * cross_axis_1() + q[2] * cross_axis_2() + q[3] * axis - t.R * child_point;
    return P;
  }
  switch (type) {
    case JointType::revolute:
      // The child turns by q about the axis: G = R(axis, q)^T.
      P.G = Eigen::AngleAxisd(q[0], axis).toRotationMatrix().transpose();
      P.rho = parent_point - P.G.transpose() * child_point;
      break;
    case JointType::prismatic:
      P.rho = parent_point - child_point + axis * q[0];
      break;
    case JointType::fixed:
      P.rho = parent_point - child_point;
      break;
    case JointType::spherical:
      P.G = quaternion_rotation(q).transpose();
      P.rho = parent_point - P.G.transpose() * child_point;
      break;
    case JointType::planar:
      P.G = Eigen::AngleAxisd(q[2], axis).toRotationMatrix().transpose();
      P.rho = parent_point + q[0] * plane_axis_1() + q[1] * plane_axis_2() - P.G.transpose() * child_point;
      break;
    case JointType::free:
      P.G = quaternion_rotation(q + 3).transpose();
      P.rho = parent_point + Vec3(q[0], q[1], q[2]) - P.G.transpose() * child_point;
      break;
    case JointType::universal:
      P.G = (Eigen::AngleAxisd(q[0], axis) * Eigen::AngleAxisd(q[1], axis2)).toRotationMatrix().transpose();
      P.rho = parent_point - P.G.transpose() * child_point;
      break;
  }
  return P;
}

Mat6 Joint::motion_axes(const double* q) const {
  // A rotation w about the joint point moves the child origin by
  // -w x r^i = r^i x w; a translation moves it by itself.
  Mat6 A = Mat6::Zero();
  if (compliant) {
    // The turn as ever; the pin's moves, seen from the child: R^T d for a
    // move d (parent frame), and the tilts' axes R^T e1 and R_axis^T e2.
    A.col(0).head<3>() = child_point.cross(axis);
    A.col(0).tail<3>() = axis;
    const CompliantTurn t = q ? compliant_turn(*this, q) : CompliantTurn{Mat3::Identity(), Mat3::Identity()};
    const Vec3 moves[] = {cross_axis_1(), cross_axis_2(), axis};
    for (int k = 0; k < 3; ++k) A.col(1 + k).head<3>() = t.R.transpose() * moves[k];
    const Vec3 tilts[] = {t.R.transpose() * cross_axis_1(), t.R_axis.transpose() * cross_axis_2()};
    for (int k = 0; k < 2; ++k) {
      A.col(4 + k).head<3>() = child_point.cross(tilts[k]);
      A.col(4 + k).tail<3>() = tilts[k];
    }
    return A;
  }
  switch (type) {
    case JointType::revolute:
      A.col(0).head<3>() = child_point.cross(axis);
      A.col(0).tail<3>() = axis;
      break;
    case JointType::prismatic:
      A.col(0).head<3>() = axis;
      break;
    case JointType::fixed:
      break;
    case JointType::spherical:
      A.block<3, 3>(0, 0) = skew(child_point);
      A.block<3, 3>(3, 0).setIdentity();
      break;
    case JointType::planar:
      // The child's in-plane velocity in its own frame (its frame turns
      // about the normal only, so e1 and e2 stay in the plane).
      A.col(0).head<3>() = plane_axis_1();
      A.col(1).head<3>() = plane_axis_2();
      A.col(2).head<3>() = child_point.cross(axis);
      A.col(2).tail<3>() = axis;
      break;
    case JointType::free:
      A.block<3, 3>(0, 0).setIdentity();
      A.block<3, 3>(0, 3) = skew(child_point);
      A.block<3, 3>(3, 3).setIdentity();
      break;
    case JointType::universal: {
      // The first axis as the child sees it after the second turn.
      const Vec3 first = q ? Vec3(Eigen::AngleAxisd(q[1], axis2).toRotationMatrix().transpose() * axis) : axis;
      A.col(0).head<3>() = child_point.cross(first);
      A.col(0).tail<3>() = first;
      A.col(1).head<3>() = child_point.cross(axis2);
      A.col(1).tail<3>() = axis2;
      break;
    }
  }
  return A;
}

Mat6 Joint::motion_axes_rate(const double* q, const double* w) const {
  Mat6 dA = Mat6::Zero();
  if (compliant) {
    // With w_c the child's rate against the parent (its frame), R^T d
    // turns as -w_c x R^T d; R_axis^T e2 turns with the hinge alone.
    const Mat6 A = motion_axes(q);
    Vec3 w_c = Vec3::Zero();
    for (int k : {0, 4, 5}) w_c += w[k] * A.col(k).tail<3>();
    for (int k = 1; k <= 3; ++k) dA.col(k).head<3>() = -w_c.cross(Vec3(A.col(k).head<3>()));
    const Vec3 turning[] = {-w_c.cross(Vec3(A.col(4).tail<3>())), -(w[0] * axis).cross(Vec3(A.col(5).tail<3>()))};
    for (int k = 0; k < 2; ++k) {
      dA.col(4 + k).head<3>() = child_point.cross(turning[k]);
      dA.col(4 + k).tail<3>() = turning[k];
    }
    return dA;
  }
  if (type != JointType::universal) return dA;
  // d/dt (R2^T a1) = -q2' a2 x (R2^T a1).
  const Vec3 first = Eigen::AngleAxisd(q[1], axis2).toRotationMatrix().transpose() * axis;
  const Vec3 turning = -w[1] * axis2.cross(first);
  dA.col(0).head<3>() = child_point.cross(turning);
  dA.col(0).tail<3>() = turning;
  return dA;
}

namespace {

// q' = q (x) (0, w) / 2 for a body-frame rate w.
void quaternion_rate(const double* q, const double* w, double* dq) {
  dq[0] = 0.5 * (-q[1] * w[0] - q[2] * w[1] - q[3] * w[2]);
  dq[1] = 0.5 * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]);
  dq[2] = 0.5 * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]);
  dq[3] = 0.5 * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
}

}  // namespace

void Joint::position_rates(const double* q, const double* w, double* dq) const {
  if (compliant) {
    for (int k = 0; k < 6; ++k) dq[k] = w[k];
    return;
  }
  switch (type) {
    case JointType::revolute:
    case JointType::prismatic: dq[0] = w[0]; break;
    case JointType::universal: dq[0] = w[0], dq[1] = w[1]; break;
    case JointType::fixed: break;
    case JointType::spherical: quaternion_rate(q, w, dq); break;
    case JointType::planar: {
      // x' = R (u1 e1 + u2 e2), R turning by q[2] in the plane.
      const double c = std::cos(q[2]), s = std::sin(q[2]);
      dq[0] = c * w[0] - s * w[1];
      dq[1] = s * w[0] + c * w[1];
      dq[2] = w[2];
      break;
    }
    case JointType::free: {
      const Vec3 x_dot = quaternion_rotation(q + 3) * Vec3(w[0], w[1], w[2]);
      for (int k = 0; k < 3; ++k) dq[k] = x_dot[k];
      quaternion_rate(q + 3, w + 3, dq + 3);
      break;
    }
  }
}

namespace {

// w = 2 vec(conj(q) (x) q') / |q|^2, the body-frame rate of q'.
void quaternion_to_rate(const double* q, const double* dq, double* w) {
  const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  w[0] = 2 * (q[0] * dq[1] - q[1] * dq[0] - q[2] * dq[3] + q[3] * dq[2]) / n2;
  w[1] = 2 * (q[0] * dq[2] - q[2] * dq[0] - q[3] * dq[1] + q[1] * dq[3]) / n2;
  w[2] = 2 * (q[0] * dq[3] - q[3] * dq[0] - q[1] * dq[2] + q[2] * dq[1]) / n2;
}

}  // namespace

void Joint::rates(const double* q, const double* dq, double* w) const {
  if (compliant) {
    for (int k = 0; k < 6; ++k) w[k] = dq[k];
    return;
  }
  switch (type) {
    case JointType::revolute:
    case JointType::prismatic: w[0] = dq[0]; break;
    case JointType::universal: w[0] = dq[0], w[1] = dq[1]; break;
    case JointType::fixed: break;
    case JointType::spherical: quaternion_to_rate(q, dq, w); break;
    case JointType::planar: {
      const double c = std::cos(q[2]), s = std::sin(q[2]);
      w[0] = c * dq[0] + s * dq[1];
      w[1] = -s * dq[0] + c * dq[1];
      w[2] = dq[2];
      break;
    }
    case JointType::free: {
      const Vec3 u = quaternion_rotation(q + 3).transpose() * Vec3(dq[0], dq[1], dq[2]);
      for (int k = 0; k < 3; ++k) w[k] = u[k];
      quaternion_to_rate(q + 3, dq + 3, w + 3);
      break;
    }
  }
}

void Joint::neutral_positions(double* q) const {
  for (int k = 0; k < positions(); ++k) q[k] = 0;
  if (has_quaternion()) q[quaternion_offset()] = 1;
}

}  // namespace unfurl::sim
