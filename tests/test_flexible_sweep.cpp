// A flexible body in the sweep against an independent formulation: a hub,
// a flexible boom hinged on it and a tip body hung on the boom's end node,
// in three dimensions. The reference builds the kinetic energy from the
// bodies' world poses (rotation matrices composed joint by joint, the node
// frame turned by x-y-z angles of the node's rotation), differentiated
// numerically: the mass matrix by polarization, dT/dq by central
// differences. The sweep's rates w = M^-1 p and its dp = dT/dq - dV/dq must
// agree with them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {
namespace {

flexible::BeamSection boom_section() {
  flexible::BeamSection s;
  s.length = 1.2, s.axial_stiffness = 4e5, s.bending_stiffness_y = 90, s.bending_stiffness_z = 140;
  s.torsional_stiffness = 60, s.mass_per_length = 0.9, s.polar_inertia_per_length = 2e-3;
  s.elements = 6;
  return s;
}

Body rigid(const std::string& name, double m, const Vec3& c, const Vec3& J) {
  Body b;
  b.name = name;
  b.mass = m;
  b.com = c;
  b.inertia_com = J.asDiagonal();
  return b;
}

struct Rig {
  SceneFile file;
  std::shared_ptr<const flexible::FlexibleBody> boom;
};

Rig rig(double zeta = 0.0, std::vector<double> dq0 = {}) {
  Rig r;
  r.boom = std::make_shared<flexible::FlexibleBody>(
      flexible::beam_body(boom_section(), 3, zeta, {Vec3(1.2, 0, 0)}));
  Body boom;
  boom.name = "boom";
  boom.flexible = r.boom;
  SceneBuilder b("flexible rig");
  b.fixed_base("ground");
  b.body(rigid("hub", 2.0, Vec3(0.1, 0.05, 0), Vec3(0.02, 0.03, 0.04)), "ground",
         Joint{"j1", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3::Zero(), Vec3::Zero()});
  b.body(boom, "hub", Joint{"j2", JointType::revolute, Vec3::UnitY(), Vec3::UnitY(), Vec3(0.3, 0, 0), Vec3::Zero()});
  b.body(rigid("tip", 0.7, Vec3(0.15, 0.02, 0.01), Vec3(0.004, 0.006, 0.005)), "boom",
         Joint{"j3", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3(1.2, 0, 0), Vec3(-0.05, 0, 0)});
  if (!dq0.empty()) {
    b.initial_rate("j1", {dq0[0]});
    b.initial_rate("j2", {dq0[1]});
    b.initial_rate("j3", {dq0[2]});
  }
  r.file = b.build();
  return r;
}

Mat3 rotation(const Vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis).toRotationMatrix(); }

// World poses (R: body to world, o: origin) of the three bodies, and the
// reference's kinetic energy at (q, q') from them.
struct Reference {
  const Rig& rig;
  const Model& model;
  int m;

  struct Poses {
    Mat3 R[3];
    Vec3 o[3];
  };

  // How far each coordinate moves the mechanism per unit: 1 for the hinges,
  // the node's largest motion for an elastic coordinate (the stiffest
  // constraint modes move the tip by metres per unit).
  Eigen::VectorXd scale() const {
    Eigen::VectorXd s = Eigen::VectorXd::Ones(3 + m);
    for (int k = 0; k < m; ++k) s[3 + k] = std::max(1.0, rig.boom->nodes[0].shape.col(k).cwiseAbs().maxCoeff());
    return s;
  }

  Poses poses(const Eigen::VectorXd& x) const {
    Poses P;
    P.R[0] = rotation(Vec3::UnitZ(), x[0]);
    P.o[0] = Vec3::Zero();
    P.R[1] = P.R[0] * rotation(Vec3::UnitY(), x[1]);
    P.o[1] = P.o[0] + P.R[0] * Vec3(0.3, 0, 0);
    const flexible::FlexibleNode& node = rig.boom->nodes[0];
    const Eigen::Matrix<double, 6, 1> s = node.shape * x.tail(m);
    const Mat3 R_node = P.R[1] * rotation(Vec3::UnitX(), s[3]) * rotation(Vec3::UnitY(), s[4]) *
                        rotation(Vec3::UnitZ(), s[5]);
    const Vec3 o_node = P.o[1] + P.R[1] * (node.point + s.head<3>());
    P.R[2] = R_node * rotation(Vec3::UnitZ(), x[2]);
    P.o[2] = o_node + R_node * (Vec3(1.2, 0, 0) - node.point) - P.R[2] * Vec3(-0.05, 0, 0);
    return P;
  }

  // The poses' rates along x' by a central difference over a step that
  // turns nothing by more than a microradian.
  double kinetic(const Eigen::VectorXd& x, const Eigen::VectorXd& x_dot) const {
    const double h = 1e-6 / std::max(1.0, (scale().asDiagonal() * x_dot).cwiseAbs().maxCoeff());
    const Poses up = poses(x + h * x_dot), down = poses(x - h * x_dot), at = poses(x);
    double T = 0;
    for (int b = 0; b < 3; ++b) {
      const Mat3 R_dot = (up.R[b] - down.R[b]) / (2 * h);
      const Mat3 W = at.R[b].transpose() * R_dot;  // body-frame angular velocity, skew
      const Vec3 w(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
      const Vec3 o_dot = at.R[b].transpose() * (up.o[b] - down.o[b]) / (2 * h);  // body frame
      if (b == 1) {
        Eigen::VectorXd V(6 + m);
        V << o_dot, 0.5 * w, x_dot.tail(m);
        T += 0.5 * V.dot(rig.boom->inertia.mass_matrix(x.tail(m)) * V);
      } else {
        const Body& body = model.bodies[b];
        const Vec3 w_half = 0.5 * w;
        const Vec3 v_c = o_dot + w_half.cross(body.com);
        T += 0.5 * body.mass * v_c.squaredNorm() + 0.5 * w_half.dot(body.inertia_com * w_half);
      }
    }
    return T;
  }
};

TEST(FlexibleSweep, RatesAndMomentumRatesMatchLagrangesEquations) {
  const Rig r = rig();
  const Scene& scene = r.file.scene;
  const Model& model = scene.model;
  const int m = r.boom->modes(), n = 3 + m;
  ASSERT_EQ(model.nv, n);
  const Reference ref{r, model, m};
  Dynamics dynamics(scene);
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(n), x_dot(n);
  const Eigen::VectorXd scale = ref.scale();
  for (int k = 0; k < n; ++k) x[k] = (k < 3 ? 1.0 : 0.002) * normal(random) / scale[k];
  for (int k = 0; k < n; ++k) x_dot[k] = normal(random) / scale[k];

  // M by polarization: T is quadratic in the rates.
  Eigen::MatrixXd M(n, n);
  for (int a = 0; a < n; ++a) M(a, a) = 2 * ref.kinetic(x, Eigen::VectorXd::Unit(n, a));
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      M(a, b) = M(b, a) = ref.kinetic(x, Eigen::VectorXd::Unit(n, a) + Eigen::VectorXd::Unit(n, b)) - M(a, a) / 2 -
                          M(b, b) / 2;
  const Eigen::VectorXd p = M * x_dot;

  std::vector<double> y(dynamics.size()), ydot(dynamics.size());
  for (int k = 0; k < n; ++k) y[k] = x[k], y[n + k] = p[k];
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  // The reference's differences leave about 1e-6 (a formula's error shows as 1e-3 or more).
  for (int k = 0; k < n; ++k) EXPECT_NEAR(ydot[k] * scale[k], x_dot[k] * scale[k], 1e-5) << "rate " << k;

  // p' = dT/dq at fixed q' - K eta, by the fourth-order central difference.
  for (int k = 0; k < n; ++k) {
    const double h = 1e-3 / scale[k];
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, k);
    double dp = (8 * (ref.kinetic(x + h * e, x_dot) - ref.kinetic(x - h * e, x_dot)) -
                 (ref.kinetic(x + 2 * h * e, x_dot) - ref.kinetic(x - 2 * h * e, x_dot))) /
                (12 * h);
    if (k >= 3) dp -= r.boom->stiffness[k - 3] * x[k];
    EXPECT_NEAR(ydot[n + k], dp, 1e-5 * std::max(1.0, std::abs(dp))) << "momentum rate " << k;
  }
}

// The accelerations pass (loads, sensors) against the rates' change along
// the motion: w' by a central difference of the sweep's rates over
// y +- h y' (h small against the stiffest mode's period, 1e-3 s).
TEST(FlexibleSweep, AccelerationsAreTheRatesRate) {
  const Rig r = rig();
  const Model& model = r.file.scene.model;
  Dynamics dynamics(r.file.scene);
  const int n = model.nv;
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  std::vector<double> y(dynamics.size()), ydot(dynamics.size()), up(dynamics.size()), down(dynamics.size()),
      f_up(dynamics.size()), f_down(dynamics.size());
  for (int k = 0; k < n; ++k) y[k] = (k < 3 ? 1.0 : 1e-4) * normal(random), y[n + k] = 0.1 * normal(random);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  const double h = 1e-8;
  for (int k = 0; k < dynamics.size(); ++k) up[k] = y[k] + h * ydot[k], down[k] = y[k] - h * ydot[k];
  ASSERT_TRUE(dynamics.rhs(0, up.data(), f_up.data()));
  ASSERT_TRUE(dynamics.rhs(0, down.data(), f_down.data()));
  std::vector<double> w_dot(n);
  ASSERT_TRUE(dynamics.rigid_accelerations(y.data(), ydot.data(), w_dot.data()));
  double largest = 0;
  for (int k = 0; k < n; ++k) largest = std::max(largest, std::abs(w_dot[k]));
  for (int k = 0; k < n; ++k)
    EXPECT_NEAR(w_dot[k], (f_up[k] - f_down[k]) / (2 * h), 1e-6 * largest) << "coordinate " << k;
}

// A free run through the whole solver: without damping the energy stays
// (kinetic, and the elastic energy the modes store as they ring); with
// modal damping what the modes dissipate balances its loss.
TEST(FlexibleSweep, ARunKeepsItsEnergyBalance) {
  for (double zeta : {0.0, 0.02}) {
    Rig r = rig(zeta, {2.0, -1.5, 3.0});
    r.file.scene.run.t_end = 2.0;
    r.file.scene.run.rtol = 1e-9;
    const RunResult run = simulate(r.file.scene, r.file.scene.run);
    ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
    const EnergyParts& first = run.trajectory.samples.front().energy;
    const EnergyParts& last = run.trajectory.samples.back().energy;
    EXPECT_GT(first.kinetic, 1.0);
    EXPECT_NEAR(last.balance(), first.balance(), 1e-6 * first.total()) << "zeta " << zeta;
    // Damped, the modes dissipate ten times what the balance's tolerance
    // could hide (6e-5 of the energy), so the balance checks the damping.
    if (zeta > 0) {
      EXPECT_GT(last.dissipated, 10 * 1e-6 * first.total());
    }
    double elastic = 0;
    for (const Sample& s : run.trajectory.samples) elastic = std::max(elastic, s.energy.springs);
    EXPECT_GT(elastic, 1e-6 * first.total()) << "the modes ring";
  }
}

}  // namespace
}  // namespace unfurl::sim
