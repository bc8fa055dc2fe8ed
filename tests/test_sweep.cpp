// The O(N) sweep against an independent formulation: for random trees the
// mass matrix Mtilde = A^T T^T M T A is built densely from the definitions
// of section 1 (S, T = S^-1, A, M), with the test's own joint kinematics;
// then
//   q' must equal Mtilde^-1 (p - b)             (b: the base-motion terms)
//   p' must equal -dH/dq + Q                    (H by finite differences)
// where H = (p - b)^T Mtilde^-1 (p - b) / 2 - c + V(q).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "closure_solver.hpp"
#include "dynamics.hpp"
#include "scene_generators.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The test's own joint placement: Rodrigues' formula, not the solver's code.
void placement(const Joint& j, double q, Mat3& G, Vec3& rho) {
  G.setIdentity();
  rho = j.parent_point - j.child_point;
  if (j.type == JointType::revolute) {
    const Mat3 e = skew(j.axis);
    const Mat3 R = Mat3::Identity() + std::sin(q) * e + (1 - std::cos(q)) * e * e;
    G = R.transpose();
    rho = j.parent_point - R * j.child_point;
  } else if (j.type == JointType::prismatic) {
    rho += j.axis * q;
  }
}

Mat6 C_of(const Mat3& G, const Vec3& rho) {
  Mat6 C = Mat6::Zero();
  C.topLeftCorner<3, 3>() = G;
  C.topRightCorner<3, 3>() = -G * skew(rho);
  C.bottomRightCorner<3, 3>() = G;
  return C;
}

// A_i of (1) from its definition, a^v = G drho/dq and a~ = G dG^T/dq, with
// the derivatives of Rodrigues' formula.
Vec6 A_of(const Joint& j, double q) {
  Vec6 A = Vec6::Zero();
  if (j.type == JointType::revolute) {
    const Mat3 e = skew(j.axis);
    const Mat3 R = Mat3::Identity() + std::sin(q) * e + (1 - std::cos(q)) * e * e;
    const Mat3 dR = std::cos(q) * e + std::sin(q) * e * e;
    A.head<3>() = R.transpose() * (-dR * j.child_point);
    const Mat3 w = R.transpose() * dR;
    A.tail<3>() << w(2, 1), w(0, 2), w(1, 0);
  } else if (j.type == JointType::prismatic) {
    A.head<3>() = j.axis;
  }
  return A;
}

struct Dense {
  MatrixXd Mt;     // A^T T^T M T A
  VectorXd b;      // A^T T^T M T v*
  double c = 0;    // v*^T T^T M T v* / 2
  MatrixXd ATTt;   // A^T T^T, to map body forces
};

Dense dense_formulation(const Scene& scene, const VectorXd& q) {
  const Model& model = scene.model;
  const int N = model.size(), n = model.nq;
  MatrixXd S = MatrixXd::Identity(6 * N, 6 * N), A = MatrixXd::Zero(6 * N, n), M = MatrixXd::Zero(6 * N, 6 * N);
  VectorXd v_star = VectorXd::Zero(6 * N);
  for (int i = 0; i < N; ++i) {
    const int c = model.coordinate[i];
    const double qi = c >= 0 ? q[c] : 0.0;
    Mat3 G;
    Vec3 rho;
    placement(model.joints[i], qi, G, rho);
    const Mat6 C = C_of(G, rho);
    if (model.parent[i] == kBase)
      v_star.segment<6>(6 * i) = C * model.base_velocity;
    else
      S.block<6, 6>(6 * i, 6 * model.parent[i]) = -C;  // (2)
    if (c >= 0) A.block<6, 1>(6 * i, c) = A_of(model.joints[i], qi);
    const Body& b = model.bodies[i];
    const Mat3 J = b.inertia_com + b.mass * (b.com.squaredNorm() * Mat3::Identity() - b.com * b.com.transpose());
    M.block<3, 3>(6 * i, 6 * i) = b.mass * Mat3::Identity();
    M.block<3, 3>(6 * i, 6 * i + 3) = -b.mass * skew(b.com);
    M.block<3, 3>(6 * i + 3, 6 * i) = b.mass * skew(b.com);
    M.block<3, 3>(6 * i + 3, 6 * i + 3) = J;
  }
  const MatrixXd T = S.inverse();  // (5)
  Dense d;
  d.ATTt = A.transpose() * T.transpose();
  d.Mt = d.ATTt * M * T * A;
  d.b = d.ATTt * M * T * v_star;
  d.c = 0.5 * v_star.dot(T.transpose() * M * T * v_star);
  return d;
}

// Orientation (base to body) and origin of every body, the test's own way.
void poses(const Scene& scene, const VectorXd& q, std::vector<Mat3>& R, std::vector<Vec3>& r) {
  const Model& model = scene.model;
  R.resize(model.size());
  r.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int c = model.coordinate[i];
    Mat3 G;
    Vec3 rho;
    placement(model.joints[i], c >= 0 ? q[c] : 0.0, G, rho);
    const int k = model.parent[i];
    const Mat3 Rk = k == kBase ? Mat3::Identity() : R[k];
    const Vec3 rk = k == kBase ? Vec3::Zero() : r[k];
    r[i] = rk + Rk.transpose() * rho;
    R[i] = G * Rk;
  }
}

double hamiltonian(const Scene& scene, const VectorXd& q, const VectorXd& p) {
  const Dense d = dense_formulation(scene, q);
  const VectorXd x = p - d.b;
  double H = 0.5 * x.dot(d.Mt.ldlt().solve(x)) - d.c;
  for (const JointSpring& s : scene.springs) {
    const double dq = q[scene.model.coordinate[s.joint]] - s.free_position;
    H += 0.5 * s.stiffness * dq * dq;
  }
  std::vector<Mat3> R;
  std::vector<Vec3> r;
  poses(scene, q, R, r);
  for (int i = 0; i < scene.model.size(); ++i) {
    const Body& b = scene.model.bodies[i];
    H -= b.mass * scene.model.gravity.dot(r[i] + R[i].transpose() * b.com);
  }
  return H;
}

// The non-conservative generalized forces: joint damping and body loads.
VectorXd applied_forces(const Scene& scene, const VectorXd& q, const VectorXd& dq) {
  const Model& model = scene.model;
  VectorXd Q = VectorXd::Zero(model.nq);
  for (const JointSpring& s : scene.springs) Q[model.coordinate[s.joint]] -= s.damping * dq[model.coordinate[s.joint]];
  std::vector<Mat3> R;
  std::vector<Vec3> r;
  poses(scene, q, R, r);
  VectorXd F = VectorXd::Zero(6 * model.size());
  for (const BodyLoad& l : scene.loads) {
    const Vec3 f = l.in_base_frame ? Vec3(R[l.body] * l.force) : l.force;
    const Vec3 m = l.in_base_frame ? Vec3(R[l.body] * l.torque) : l.torque;
    F.segment<3>(6 * l.body) += f;
    F.segment<3>(6 * l.body + 3) += m + l.point.cross(f);
  }
  return Q + dense_formulation(scene, q).ATTt * F;
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

Scene random_tree(std::mt19937& rng, int N, bool moving_base) {
  std::uniform_real_distribution<double> U(-1, 1);
  Scene scene;
  Model& model = scene.model;
  for (int i = 0; i < N; ++i) {
    Body b;
    b.name = "b" + std::to_string(i);
    b.mass = 0.1 + 5 * (U(rng) + 1);
    b.com = 0.3 * Vec3(U(rng), U(rng), U(rng));
    const Mat3 Q = Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix();
    const Vec3 principal(0.01 + 0.5 * (U(rng) + 1), 0.01 + 0.5 * (U(rng) + 1), 0.01 + 0.5 * (U(rng) + 1));
    b.inertia_com = Q * principal.asDiagonal() * Q.transpose();
    Joint j;
    j.name = "j" + std::to_string(i);
    const double kind = U(rng);
    j.type = kind < 0.7 ? JointType::revolute : kind < 0.9 ? JointType::prismatic : JointType::fixed;
    j.axis = random_unit(rng);
    j.parent_point = 0.5 * Vec3(U(rng), U(rng), U(rng));
    j.child_point = 0.5 * Vec3(U(rng), U(rng), U(rng));
    model.bodies.push_back(b);
    model.joints.push_back(j);
    model.parent.push_back(std::uniform_int_distribution<int>(-1, i - 1)(rng));
  }
  if (moving_base) {
    for (int k = 0; k < 6; ++k) model.base_velocity[k] = U(rng);
  } else {
    model.gravity = Vec3(U(rng), U(rng), -9.81);
  }
  model.finalize();
  for (int i = 0; i < N; ++i) {
    if (model.coordinate[i] < 0) continue;
    if (U(rng) > 0) scene.springs.push_back({i, 2 * (U(rng) + 1), U(rng), 0.5 * (U(rng) + 1)});
    if (U(rng) > 0.5)
      scene.loads.push_back({i, Vec3(U(rng), U(rng), U(rng)), Vec3(U(rng), U(rng), U(rng)),
                             Vec3(U(rng), U(rng), U(rng)), !moving_base && U(rng) > 0});
  }
  scene.q0.assign(model.nq, 0.0);
  for (double& x : scene.q0) x = 3 * U(rng);
  scene.dq0.assign(model.nq, 0.0);
  return scene;
}

double relative_error(const VectorXd& x, const VectorXd& reference) {
  return (x - reference).norm() / std::max(reference.norm(), 1e-300);
}

class RandomTrees : public ::testing::TestWithParam<int> {};

TEST_P(RandomTrees, SweepMatchesTheDenseHamiltonianFormulation) {
  std::mt19937 rng(GetParam());
  const int N = 1 + GetParam() % 30;
  const Scene scene = random_tree(rng, N, GetParam() % 3 == 0);
  const int n = scene.model.nq;
  if (n == 0) GTEST_SKIP() << "only fixed joints";
  Dynamics dynamics(scene);
  std::uniform_real_distribution<double> U(-1, 1);
  VectorXd y(2 * n);
  for (int k = 0; k < n; ++k) {
    y[k] = scene.q0[k];
    y[n + k] = 5 * U(rng);
  }
  VectorXd ydot(2 * n);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  const VectorXd q = y.head(n), p = y.tail(n);

  const Dense d = dense_formulation(scene, q);
  const VectorXd dq_expected = d.Mt.ldlt().solve(p - d.b);
  EXPECT_LT(relative_error(ydot.head(n), dq_expected), 1e-7) << N << " bodies";

  // -dH/dq by fourth-order central differences.
  VectorXd dp_expected(n);
  const double h = 1e-4;
  for (int k = 0; k < n; ++k) {
    auto H_at = [&](double dx) {
      VectorXd qs = q;
      qs[k] += dx;
      return hamiltonian(scene, qs, p);
    };
    dp_expected[k] = -(-H_at(2 * h) + 8 * H_at(h) - 8 * H_at(-h) + H_at(-2 * h)) / (12 * h);
  }
  dp_expected += applied_forces(scene, q, dq_expected);
  EXPECT_LT(relative_error(ydot.tail(n), dp_expected), 1e-7) << N << " bodies";
}

INSTANTIATE_TEST_SUITE_P(UpTo30Bodies, RandomTrees, ::testing::Range(1, 41));

// W = J Mtilde^-1 J^T with J = eps T A from the dense formulation.
MatrixXd dense_mobility(const Scene& scene, const std::vector<LoopComponent>& components, const VectorXd& q) {
  const Dense d = dense_formulation(scene, q);
  const int m = static_cast<int>(components.size());
  // eps T A = rows of (A^T T^T eps^T)^T; ATTt maps a body force to Q.
  MatrixXd J(m, scene.model.nq);
  for (int c = 0; c < m; ++c) {
    const LoopComponent& lc = components[c];
    VectorXd F = VectorXd::Zero(6 * scene.model.size());
    F[6 * scene.loops[lc.loop].body + lc.axis] = 1;
    F[6 * scene.loops[lc.loop].image + lc.axis] = -1;
    J.row(c) = (d.ATTt * F).transpose();
  }
  return J * d.Mt.ldlt().solve(J.transpose());
}

TEST(Sweep, LoopMobilityFromExtraPassesEqualsDenseFormula) {
  // W = eps T A Mtilde^-1 (eps T A)^T on the active components, by the
  // regulator's m passes of the sweep and densely.
  const Scene scene = test::scene_file("pantograph");
  Dynamics dynamics(scene);
  Regulator& regulator = *dynamics.regulator();
  const int n = scene.model.nq, m = regulator.size();
  VectorXd q(n);
  for (int k = 0; k < n; ++k) q[k] = 0.7 * scene.q0[k];
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  const MatrixXd W = regulator.mobility(sweep);

  const MatrixXd W_dense = dense_mobility(scene, regulator.components(), q);
  EXPECT_LT((W - W_dense).norm(), 1e-10 * W_dense.norm());
  EXPECT_EQ(m, W.rows());
}

TEST(Sweep, JointDiagonalSolvesWithMassMatrixPlusDiagonal) {
  // The preconditioner's passes: (Mtilde + diag k) dq = p.
  const Scene scene = test::scene_file("pantograph");
  const int n = scene.model.nq;
  VectorXd q(n), k(n), p = VectorXd::LinSpaced(n, -1, 2);
  for (int c = 0; c < n; ++c) {
    q[c] = 0.6 * scene.q0[c] + 0.05 * c;
    k[c] = 0.3 + 0.1 * c;
  }
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data(), k.data());
  std::vector<Vec6> phi(scene.model.size()), v(scene.model.size());
  VectorXd dq(n);
  sweep.bias(p.data(), phi);
  sweep.velocities(p.data(), phi, Vec6::Zero(), dq.data(), v);
  MatrixXd K = dense_formulation(scene, q).Mt;
  K.diagonal() += k;
  EXPECT_LT(relative_error(dq, K.ldlt().solve(p)), 1e-12);
}

// R^-1 b = (W + delta I)^-1 b by a closure solver at q, and densely.
void expect_closure_solve_matches_dense(const Scene& scene, ClosureSolverKind kind, const VectorXd& q,
                                        double delta) {
  Dynamics dynamics(scene);
  const std::vector<LoopComponent>& components = dynamics.regulator()->components();
  const int m = static_cast<int>(components.size());
  const auto solver = make_closure_solver(kind, scene.model, scene.loops, components);
  Sweep sweep(scene.model);
  sweep.set_configuration(q.data());
  ASSERT_TRUE(solver->factorize(sweep, delta));
  // Two right-hand sides at once, as the regulator solves them.
  MatrixXd B(m, 2);
  B.col(0) = VectorXd::LinSpaced(m, -1, 1) + VectorXd::Constant(m, 0.25);
  B.col(1) = VectorXd::LinSpaced(m, 2, -0.5);
  MatrixXd X(m, 2);
  solver->solve(B.data(), X.data(), 2);
  MatrixXd R = dense_mobility(scene, components, q);
  R.diagonal().array() += delta;
  for (int c = 0; c < 2; ++c)
    EXPECT_LT(relative_error(X.col(c), R.ldlt().solve(B.col(c))), 1e-9) << m << " components, delta " << delta;
}

TEST(ClosureSolver, DenseAndSparseSolveWithWPlusDelta) {
  const Scene scene = test::scene_file("pantograph");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.7 * scene.q0[k];
  for (const auto kind : {ClosureSolverKind::dense, ClosureSolverKind::sparse})
    expect_closure_solve_matches_dense(scene, kind, q, 1e-5);
}

TEST(ClosureSolver, SparseHoldsAtTheDeployedBranchPoint) {
  // At q = 0 W loses rank: R = W + delta I is what keeps the solve defined.
  const Scene scene = test::scene_file("pantograph");
  const VectorXd q = VectorXd::Zero(scene.model.nq);
  for (const double delta : {1e-3, 1e-5, 1e-7})
    expect_closure_solve_matches_dense(scene, ClosureSolverKind::sparse, q, delta);
}

TEST(ClosureSolver, SparseOnTenLoops) {
  const Scene scene = load_scene_text(generate_pantograph(10), "pantograph_10");
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.5 * scene.q0[k];
  expect_closure_solve_matches_dense(scene, ClosureSolverKind::sparse, q, 1e-5);
}

}  // namespace
}  // namespace unfurl
