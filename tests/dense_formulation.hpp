// The tests' own, independent formulation of a tree's dynamics: the dense
// matrices of section 1 (S, T = S^-1, A, M) built from the definitions with
// the test's own joint kinematics (Rodrigues' formula), not the solver's
// code; and random trees to run it on.
#pragma once

#include <Eigen/Dense>
#include <random>
#include <string>
#include <vector>

#include "unfurl/sim/loop.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/scene.hpp"

namespace unfurl::test {

using MatrixXd = Eigen::MatrixXd;
using VectorXd = Eigen::VectorXd;

// Rodrigues' formula: the rotation by angle q about unit axis a.
inline sim::Mat3 rodrigues(const sim::Vec3& a, double q) {
  const sim::Mat3 e = sim::skew(a);
  return sim::Mat3::Identity() + std::sin(q) * e + (1 - std::cos(q)) * e * e;
}

// The rotation of a quaternion (w, x, y, z), normalized, written out.
inline sim::Mat3 quaternion_matrix(const double* q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  sim::Mat3 R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

// a (x) b for quaternions (w, x, y, z).
inline Eigen::Vector4d quaternion_product(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  const sim::Vec3 u = a.tail<3>(), v = b.tail<3>();
  Eigen::Vector4d out;
  out[0] = a[0] * b[0] - u.dot(v);
  out.tail<3>() = a[0] * v + b[0] * u + u.cross(v);
  return out;
}

// The test's own joint placement: Rodrigues' formula and the quaternion's
// matrix written out, not the solver's code. q: the joint's positions.
inline void placement(const sim::Joint& j, const double* q, sim::Mat3& G, sim::Vec3& rho) {
  G.setIdentity();
  rho = j.parent_point - j.child_point;
  sim::Mat3 R = sim::Mat3::Identity();
  if (j.compliant) {
    // The pin tilted about e1, then e2, the child turned about the axis;
    // the pin moved by (q1, q2, q3) along e1, e2 and the axis.
    const sim::Vec3 e1 = j.axis.unitOrthogonal(), e2 = j.axis.cross(e1);
    R = rodrigues(e1, q[4]) * rodrigues(e2, q[5]) * rodrigues(j.axis, q[0]);
    G = R.transpose();
    rho = j.parent_point + q[1] * e1 + q[2] * e2 + q[3] * j.axis - R * j.child_point;
    return;
  }
  switch (j.type) {
    case sim::JointType::revolute:
      R = rodrigues(j.axis, q[0]);
      break;
    case sim::JointType::prismatic:
      rho += j.axis * q[0];
      break;
    case sim::JointType::fixed:
      break;
    case sim::JointType::spherical:
      R = quaternion_matrix(q);
      break;
    case sim::JointType::planar: {
      const sim::Vec3 e1 = j.axis.unitOrthogonal(), e2 = j.axis.cross(e1);
      R = rodrigues(j.axis, q[2]);
      rho += q[0] * e1 + q[1] * e2;
      break;
    }
    case sim::JointType::free:
      R = quaternion_matrix(q + 3);
      rho += sim::Vec3(q[0], q[1], q[2]);
      break;
    case sim::JointType::universal:
      R = rodrigues(j.axis, q[0]) * rodrigues(j.axis2, q[1]);
      break;
  }
  G = R.transpose();
  rho += j.child_point - R * j.child_point;
}

// The positions moved by eps along velocity coordinate k: the child turned
// by eps about its own axis e_k (a quaternion times exp(eps e_k / 2)), or
// moved by eps along its own e_k; what a unit rate does in unit time.
inline std::vector<double> moved(const sim::Joint& j, const double* q, int k, double eps) {
  std::vector<double> out(q, q + j.positions());
  const auto turn = [&](int at, int axis) {
    Eigen::Vector4d dq(std::cos(eps / 2), 0, 0, 0);
    dq[1 + axis] = std::sin(eps / 2);
    const Eigen::Vector4d r = quaternion_product(Eigen::Vector4d(q[at], q[at + 1], q[at + 2], q[at + 3]), dq);
    for (int a = 0; a < 4; ++a) out[at + a] = r[a];
  };
  switch (j.type) {
    case sim::JointType::spherical:
      turn(0, k);
      break;
    case sim::JointType::free:
      if (k >= 3) {
        turn(3, k - 3);
      } else {
        const sim::Vec3 x = quaternion_matrix(q + 3).col(k) * eps;
        for (int a = 0; a < 3; ++a) out[a] += x[a];
      }
      break;
    case sim::JointType::planar:
      if (k == 2) {
        out[2] += eps;
      } else {
        // The child's own in-plane axis e_k, in the plane's coordinates.
        const double c = std::cos(q[2]), s = std::sin(q[2]);
        out[0] += eps * (k == 0 ? c : -s);
        out[1] += eps * (k == 0 ? s : c);
      }
      break;
    default: out[k] += eps;  // q' = w
  }
  return out;
}

inline sim::Mat6 C_of(const sim::Mat3& G, const sim::Vec3& rho) {
  sim::Mat6 C = sim::Mat6::Zero();
  C.topLeftCorner<3, 3>() = G;
  C.topRightCorner<3, 3>() = -G * sim::skew(rho);
  C.bottomRightCorner<3, 3>() = G;
  return C;
}

// A_i of (1) from its definition, a^v = G drho/dq and a~ = G dG^T/dq, with
// the derivatives of Rodrigues' formula.
inline sim::Vec6 A_of(const sim::Joint& j, double q);

// A_i of (1), 6 x n_i, for any joint: the columns a^v = G drho and
// a~ = G dG^T along each velocity coordinate (moved()), by central
// differences of the test's placement.
inline Eigen::Matrix<double, 6, Eigen::Dynamic> A_of(const sim::Joint& j, const double* q) {
  Eigen::Matrix<double, 6, Eigen::Dynamic> A(6, j.dof());
  if (j.is_scalar()) {
    A.col(0) = A_of(j, q[0]);
    return A;
  }
  if (j.type == sim::JointType::universal) {
    // G dG^T/dq1 = R2^T a1~ R2 and G dG^T/dq2 = a2~ for G = (R1 R2)^T, in
    // closed form: dH/dq by differences of H needs A to round-off.
    const sim::Vec3 w1 = rodrigues(j.axis2, q[1]).transpose() * j.axis;
    A.col(0) << j.child_point.cross(w1), w1;
    A.col(1) << j.child_point.cross(j.axis2), j.axis2;
    return A;
  }
  sim::Mat3 G;
  sim::Vec3 rho;
  placement(j, q, G, rho);
  if (j.compliant) {
    // Fourth-order differences (q' = w): A to near round-off, as the
    // Hamiltonian's differences need.
    const double h = 1e-3;
    for (int k = 0; k < j.dof(); ++k) {
      sim::Mat3 Gs[4];
      sim::Vec3 rs[4];
      const double steps[] = {2 * h, h, -h, -2 * h};
      for (int s = 0; s < 4; ++s) placement(j, moved(j, q, k, steps[s]).data(), Gs[s], rs[s]);
      A.col(k).head<3>() = G * (-rs[0] + 8 * rs[1] - 8 * rs[2] + rs[3]) / (12 * h);
      const sim::Mat3 w =
          G * (-Gs[0].transpose() + 8 * Gs[1].transpose() - 8 * Gs[2].transpose() + Gs[3].transpose()) / (12 * h);
      A.col(k).tail<3>() << w(2, 1), w(0, 2), w(1, 0);
    }
    return A;
  }
  const double eps = 1e-6;
  for (int k = 0; k < j.dof(); ++k) {
    sim::Mat3 Gp, Gm;
    sim::Vec3 rp, rm;
    placement(j, moved(j, q, k, eps).data(), Gp, rp);
    placement(j, moved(j, q, k, -eps).data(), Gm, rm);
    A.col(k).head<3>() = G * (rp - rm) / (2 * eps);
    const sim::Mat3 w = G * (Gp.transpose() - Gm.transpose()) / (2 * eps);
    A.col(k).tail<3>() << w(2, 1), w(0, 2), w(1, 0);
  }
  return A;
}

inline sim::Vec6 A_of(const sim::Joint& j, double q) {
  sim::Vec6 A = sim::Vec6::Zero();
  if (j.type == sim::JointType::revolute) {
    const sim::Mat3 e = sim::skew(j.axis);
    const sim::Mat3 R = sim::Mat3::Identity() + std::sin(q) * e + (1 - std::cos(q)) * e * e;
    const sim::Mat3 dR = std::cos(q) * e + std::sin(q) * e * e;
    A.head<3>() = R.transpose() * (-dR * j.child_point);
    const sim::Mat3 w = R.transpose() * dR;
    A.tail<3>() << w(2, 1), w(0, 2), w(1, 0);
  } else if (j.type == sim::JointType::prismatic) {
    A.head<3>() = j.axis;
  }
  return A;
}

struct Dense {
  MatrixXd Mt;     // A^T T^T M T A
  VectorXd b;      // A^T T^T M T v*
  double c = 0;    // v*^T T^T M T v* / 2
  MatrixXd ATTt;   // A^T T^T, to map body forces
  MatrixXd T;      // S^-1 of (5)
};

inline Dense dense_formulation(const sim::Scene& scene, const VectorXd& q) {
  const sim::Model& model = scene.model;
  const int N = model.size(), n = model.nv;
  MatrixXd S = MatrixXd::Identity(6 * N, 6 * N), A = MatrixXd::Zero(6 * N, n), M = MatrixXd::Zero(6 * N, 6 * N);
  VectorXd v_star = VectorXd::Zero(6 * N);
  const double none = 0;
  for (int i = 0; i < N; ++i) {
    const int c = model.first_position[i].value;
    const double* qi = c >= 0 ? &q[c] : &none;
    sim::Mat3 G;
    sim::Vec3 rho;
    placement(model.joints[i], qi, G, rho);
    const sim::Mat6 C = C_of(G, rho);
    if (model.parent[i] == sim::kBase)
      v_star.segment<6>(6 * i) = C * model.base_velocity;
    else
      S.block<6, 6>(6 * i, 6 * model.parent[i]) = -C;  // (2)
    if (c >= 0) A.block(6 * i, model.first_velocity[i].value, 6, model.joints[i].dof()) = A_of(model.joints[i], qi);
    const sim::Body& b = model.bodies[i];
    const sim::Mat3 J =
        b.inertia_com + b.mass * (b.com.squaredNorm() * sim::Mat3::Identity() - b.com * b.com.transpose());
    M.block<3, 3>(6 * i, 6 * i) = b.mass * sim::Mat3::Identity();
    M.block<3, 3>(6 * i, 6 * i + 3) = -b.mass * sim::skew(b.com);
    M.block<3, 3>(6 * i + 3, 6 * i) = b.mass * sim::skew(b.com);
    M.block<3, 3>(6 * i + 3, 6 * i + 3) = J;
  }
  const MatrixXd T = S.inverse();  // (5)
  Dense d;
  d.T = T;
  d.ATTt = A.transpose() * T.transpose();
  d.Mt = d.ATTt * M * T * A;
  d.b = d.ATTt * M * T * v_star;
  d.c = 0.5 * v_star.dot(T.transpose() * M * T * v_star);
  return d;
}

// Orientation (base to body) and origin of every body, the test's own way.
inline void poses(const sim::Scene& scene, const VectorXd& q, std::vector<sim::Mat3>& R, std::vector<sim::Vec3>& r) {
  const sim::Model& model = scene.model;
  R.resize(model.size());
  r.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int c = model.first_position[i].value;
    const double none = 0;
    sim::Mat3 G;
    sim::Vec3 rho;
    placement(model.joints[i], c >= 0 ? &q[c] : &none, G, rho);
    const int k = model.parent[i];
    const sim::Mat3 Rk = k == sim::kBase ? sim::Mat3::Identity() : R[k];
    const sim::Vec3 rk = k == sim::kBase ? sim::Vec3::Zero() : r[k];
    r[i] = rk + Rk.transpose() * rho;
    R[i] = G * Rk;
  }
}

inline double hamiltonian(const sim::Scene& scene, const VectorXd& q, const VectorXd& p) {
  const Dense d = dense_formulation(scene, q);
  const VectorXd x = p - d.b;
  double H = 0.5 * x.dot(d.Mt.ldlt().solve(x)) - d.c;
  for (const sim::JointSpring* s : scene.elements_of<sim::JointSpring>()) {
    const double dq = q[scene.model.position_of(s->joint).value] - s->free_position;
    H += 0.5 * s->stiffness * dq * dq;
  }
  std::vector<sim::Mat3> R;
  std::vector<sim::Vec3> r;
  poses(scene, q, R, r);
  for (int i = 0; i < scene.model.size(); ++i) {
    const sim::Body& b = scene.model.bodies[i];
    H -= b.mass * scene.gravity().dot(r[i] + R[i].transpose() * b.com);
  }
  return H;
}

// The applied body forces (loads, and gravity if asked) at the body
// origins, body frames, stacked 6 per body.
inline VectorXd body_forces(const sim::Scene& scene, const VectorXd& q, bool with_gravity) {
  const sim::Model& model = scene.model;
  std::vector<sim::Mat3> R;
  std::vector<sim::Vec3> r;
  poses(scene, q, R, r);
  VectorXd F = VectorXd::Zero(6 * model.size());
  for (const sim::AppliedForce* l : scene.elements_of<sim::AppliedForce>()) {
    const sim::Vec3 f = l->in_base_frame ? sim::Vec3(R[l->body] * l->force) : l->force;
    const sim::Vec3 m = l->in_base_frame ? sim::Vec3(R[l->body] * l->torque) : l->torque;
    F.segment<3>(6 * l->body) += f;
    F.segment<3>(6 * l->body + 3) += m + l->point.cross(f);
  }
  for (int i = 0; i < model.size() && with_gravity; ++i) {
    const sim::Vec3 f = R[i] * (model.bodies[i].mass * scene.gravity());
    F.segment<3>(6 * i) += f;
    F.segment<3>(6 * i + 3) += model.bodies[i].com.cross(f);
  }
  return F;
}

// The non-conservative generalized forces: joint damping and body loads
// (gravity is in the Hamiltonian).
inline VectorXd applied_forces(const sim::Scene& scene, const VectorXd& q, const VectorXd& dq) {
  const sim::Model& model = scene.model;
  VectorXd Q = VectorXd::Zero(model.nv);
  for (const sim::JointSpring* s : scene.elements_of<sim::JointSpring>())
    Q[model.velocity_of(s->joint).value] -= s->damping * dq[model.velocity_of(s->joint).value];
  return Q + dense_formulation(scene, q).ATTt * body_forces(scene, q, false);
}

inline double relative_error(const VectorXd& x, const VectorXd& reference) {
  return (x - reference).norm() / std::max(reference.norm(), 1e-300);
}

inline sim::Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return sim::Vec3(n(rng), n(rng), n(rng)).normalized();
}

// With multi_dof, a fifth of the joints are spherical, planar or free.
inline sim::Scene random_tree(std::mt19937& rng, int N, bool moving_base, bool multi_dof = false) {
  std::uniform_real_distribution<double> U(-1, 1);
  sim::Scene scene;
  sim::Model& model = scene.model;
  for (int i = 0; i < N; ++i) {
    sim::Body b;
    b.name = "b" + std::to_string(i);
    b.mass = 0.1 + 5 * (U(rng) + 1);
    b.com = 0.3 * sim::Vec3(U(rng), U(rng), U(rng));
    const sim::Mat3 Q = Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix();
    const sim::Vec3 principal(0.01 + 0.5 * (U(rng) + 1), 0.01 + 0.5 * (U(rng) + 1), 0.01 + 0.5 * (U(rng) + 1));
    b.inertia_com = Q * principal.asDiagonal() * Q.transpose();
    sim::Joint j;
    j.name = "j" + std::to_string(i);
    const double kind = U(rng);
    j.type = kind < 0.7 ? sim::JointType::revolute : kind < 0.9 ? sim::JointType::prismatic : sim::JointType::fixed;
    if (multi_dof && (U(rng) > 0.6 || i == N / 2)) {
      const double which = U(rng);
      j.type = which < -0.3  ? sim::JointType::spherical
               : which < 0.2 ? sim::JointType::universal
               : which < 0.6 ? sim::JointType::planar
                             : sim::JointType::free;
      j.axis2 = random_unit(rng);
    }
    // A compliant hinge now and then (its pin's coordinates free here).
    if (multi_dof && j.type == sim::JointType::revolute && U(rng) > 0.5) j.compliant = true;
    j.axis = random_unit(rng);
    j.parent_point = 0.5 * sim::Vec3(U(rng), U(rng), U(rng));
    j.child_point = 0.5 * sim::Vec3(U(rng), U(rng), U(rng));
    model.bodies.push_back(b);
    model.joints.push_back(j);
    model.parent.push_back(std::uniform_int_distribution<int>(-1, i - 1)(rng));
  }
  sim::Vec3 gravity = sim::Vec3::Zero();
  if (moving_base) {
    for (int k = 0; k < 6; ++k) model.base_velocity[k] = U(rng);
  } else {
    gravity = sim::Vec3(U(rng), U(rng), -9.81);
  }
  model.finalize();
  for (int i = 0; i < N; ++i) {
    if (!model.joints[i].is_scalar()) continue;
    if (U(rng) > 0) {
      auto s = std::make_shared<sim::JointSpring>(i);
      s->stiffness = 2 * (U(rng) + 1);
      s->free_position = U(rng);
      s->damping = 0.5 * (U(rng) + 1);
      scene.elements.push_back(s);
    }
    if (U(rng) > 0.5) {
      auto load = std::make_shared<sim::AppliedForce>();
      load->body = i;
      load->force = sim::Vec3(U(rng), U(rng), U(rng));
      load->torque = sim::Vec3(U(rng), U(rng), U(rng));
      load->point = sim::Vec3(U(rng), U(rng), U(rng));
      load->in_base_frame = !moving_base && U(rng) > 0;
      scene.elements.push_back(load);
    }
  }
  if (!gravity.isZero(0)) scene.elements.push_back(std::make_shared<sim::Gravity>(gravity));
  scene.q0.assign(model.nq, 0.0);
  for (double& x : scene.q0) x = 3 * U(rng);  // a quaternion's norm does not matter
  scene.dq0.assign(model.nv, 0.0);
  return scene;
}

// W = J Mtilde^-1 J^T with J = eps T A from the dense formulation.
inline MatrixXd dense_mobility(const sim::Scene& scene, const std::vector<sim::LoopComponent>& components,
                               const VectorXd& q) {
  const Dense d = dense_formulation(scene, q);
  const int m = static_cast<int>(components.size());
  // eps T A = rows of (A^T T^T eps^T)^T; ATTt maps a body force to Q.
  MatrixXd J(m, scene.model.nv);
  for (int c = 0; c < m; ++c) {
    const sim::LoopComponent& lc = components[c];
    VectorXd F = VectorXd::Zero(6 * scene.model.size());
    F[6 * scene.loops[lc.loop].body + lc.axis] = 1;
    F[6 * scene.loops[lc.loop].image + lc.axis] = -1;
    J.row(c) = (d.ATTt * F).transpose();
  }
  return J * d.Mt.ldlt().solve(J.transpose());
}

}  // namespace unfurl::test
