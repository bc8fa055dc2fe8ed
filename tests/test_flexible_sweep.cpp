// A flexible body in the sweep against an independent formulation: a hub,
// a flexible boom hinged on it (by a revolute, a universal or a compliant
// revolute joint) and a tip body hung on the boom's end node, in three
// dimensions. The reference builds the kinetic energy from the
// bodies' world poses (rotation matrices composed joint by joint, the node
// frame turned by x-y-z angles of the node's rotation), differentiated
// numerically: the mass matrix by polarization, dT/dq by central
// differences. The sweep's rates w = M^-1 p and its dp = dT/dq - dV/dq must
// agree with them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <ostream>
#include <random>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/elements/joint_compliance.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

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

Body flexible_boom(double zeta = 0.0) {
  Body boom;
  boom.name = "boom";
  boom.flexible = std::make_shared<flexible::FlexibleBody>(flexible::beam_body(boom_section(), 3, zeta, {Vec3(1.2, 0, 0)}));
  return boom;
}

// The boom's own joint, the tested generalization's three kinds.
enum class BoomJoint { revolute, universal, compliant };

// The compliant hinge's pin (radial, axial N/m; tilt N m/rad), stiff
// enough to ring well above the boom's first modes.
constexpr double kRadial = 4e4, kAxial = 6e4, kTilt = 900;

Joint boom_joint(BoomJoint kind) {
  Joint j{"j2", JointType::revolute, Vec3::UnitY(), Vec3::UnitZ(), Vec3(0.3, 0, 0), Vec3::Zero()};
  if (kind == BoomJoint::universal) j.type = JointType::universal;
  j.compliant = kind == BoomJoint::compliant;
  return j;
}

struct Rig {
  SceneFile file;
  std::shared_ptr<const flexible::FlexibleBody> boom;
  BoomJoint kind = BoomJoint::revolute;
};

Rig rig(double zeta = 0.0, std::vector<double> dq0 = {}, BoomJoint kind = BoomJoint::revolute) {
  Rig r;
  const Body boom = flexible_boom(zeta);
  r.boom = boom.flexible;
  SceneBuilder b("flexible rig");
  b.fixed_base("ground");
  b.body(rigid("hub", 2.0, Vec3(0.1, 0.05, 0), Vec3(0.02, 0.03, 0.04)), "ground",
         Joint{"j1", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3::Zero(), Vec3::Zero()});
  b.body(boom, "hub", boom_joint(kind));
  if (kind == BoomJoint::compliant) {
    auto pin = std::make_shared<JointCompliance>();
    pin->joint = 1, pin->radial = kRadial, pin->axial = kAxial, pin->tilt = kTilt;
    b.element(pin);
  }
  b.body(rigid("tip", 0.7, Vec3(0.15, 0.02, 0.01), Vec3(0.004, 0.006, 0.005)), "boom",
         Joint{"j3", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3(1.2, 0, 0), Vec3(-0.05, 0, 0)});
  if (!dq0.empty()) {
    b.initial_rate("j1", {dq0[0]});
    // A compliant hinge's pin moves at a hundredth of the turn's rate (as
    // the turn sets it ringing): at 1.5 m/s and rad/s the boom would bend
    // by metres, far beyond its linear model.
    std::vector<double> w(boom_joint(kind).dof(), kind == BoomJoint::compliant ? 0.01 * dq0[1] : dq0[1]);
    w[0] = dq0[1];
    b.initial_rate("j2", w);
    b.initial_rate("j3", {dq0[2]});
  }
  r.file = b.build();
  r.kind = kind;
  return r;
}

Mat3 rotation(const Vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis).toRotationMatrix(); }

// World poses (R: body to world, o: origin) of the three bodies, and the
// reference's kinetic energy at (q, q') from them. Coordinates are the
// model's: j1 and j3 first (one each), then j2's, then the boom's eta.
struct Reference {
  const Rig& rig;
  const Model& model;
  int m;

  int j2() const { return model.first_velocity[1].value; }
  int eta() const { return model.first_elastic_velocity[1]; }
  int joint_dof() const { return model.joints[1].dof(); }
  bool elastic(int k) const { return k >= eta(); }

  // The boom joint's rotation (child to parent) and its point's move, as
  // joint.hpp defines each kind, written out here.
  Mat3 joint_rotation(const Eigen::VectorXd& x) const {
    const Joint& j = model.joints[1];
    switch (rig.kind) {
      case BoomJoint::universal: return rotation(j.axis, x[j2()]) * rotation(j.axis2, x[j2() + 1]);
      case BoomJoint::compliant:
        return rotation(j.axis.unitOrthogonal(), x[j2() + 4]) *
               rotation(j.axis.cross(j.axis.unitOrthogonal()), x[j2() + 5]) * rotation(j.axis, x[j2()]);
      default: return rotation(j.axis, x[j2()]);
    }
  }
  Vec3 joint_move(const Eigen::VectorXd& x) const {
    if (rig.kind != BoomJoint::compliant) return Vec3::Zero();
    const Vec3 a = model.joints[1].axis, e1 = a.unitOrthogonal(), e2 = a.cross(e1);
    return x[j2() + 1] * e1 + x[j2() + 2] * e2 + x[j2() + 3] * a;
  }
  // The pin's springs' generalized forces (joint_compliance.hpp: -k x).
  double pin_force(const Eigen::VectorXd& x, int k) const {
    if (rig.kind != BoomJoint::compliant || k <= j2() || k >= j2() + 6) return 0;
    const double stiffness[] = {kRadial, kRadial, kAxial, kTilt, kTilt};
    return -stiffness[k - j2() - 1] * x[k];
  }

  struct Poses {
    Mat3 R[3];
    Vec3 o[3];
  };

  // How far each coordinate moves the mechanism per unit: 1 for the hinges,
  // the node's largest motion for an elastic coordinate (the stiffest
  // constraint modes move the tip by metres per unit).
  Eigen::VectorXd scale() const {
    Eigen::VectorXd s = Eigen::VectorXd::Ones(model.nv);
    for (int k = 0; k < m; ++k) s[eta() + k] = std::max(1.0, rig.boom->nodes[0].shape.col(k).cwiseAbs().maxCoeff());
    return s;
  }

  Poses poses(const Eigen::VectorXd& x) const {
    Poses P;
    P.R[0] = rotation(Vec3::UnitZ(), x[0]);
    P.o[0] = Vec3::Zero();
    P.R[1] = P.R[0] * joint_rotation(x);
    P.o[1] = P.o[0] + P.R[0] * (Vec3(0.3, 0, 0) + joint_move(x));
    const flexible::FlexibleNode& node = rig.boom->nodes[0];
    const Eigen::Matrix<double, 6, 1> s = node.shape * x.segment(eta(), m);
    const Mat3 R_node = P.R[1] * rotation(Vec3::UnitX(), s[3]) * rotation(Vec3::UnitY(), s[4]) *
                        rotation(Vec3::UnitZ(), s[5]);
    const Vec3 o_node = P.o[1] + P.R[1] * (node.point + s.head<3>());
    P.R[2] = R_node * rotation(Vec3::UnitZ(), x[model.first_velocity[2].value]);
    P.o[2] = o_node + R_node * (Vec3(1.2, 0, 0) - node.point) - P.R[2] * Vec3(-0.05, 0, 0);
    return P;
  }

  // The poses' rates along x' by the fourth-order central difference over
  // steps that turn nothing by more than 0.1 mrad (a second-order one over
  // microradians left round-off of 1e-5 in the stiff modes' rates).
  double kinetic(const Eigen::VectorXd& x, const Eigen::VectorXd& x_dot) const {
    const double h = 1e-4 / std::max(1.0, (scale().asDiagonal() * x_dot).cwiseAbs().maxCoeff());
    const Poses up = poses(x + h * x_dot), down = poses(x - h * x_dot), up2 = poses(x + 2 * h * x_dot),
                down2 = poses(x - 2 * h * x_dot), at = poses(x);
    const auto rate = [h](const auto& f_up, const auto& f_down, const auto& f_up2, const auto& f_down2) {
      return ((8 * (f_up - f_down) - (f_up2 - f_down2)) / (12 * h)).eval();
    };
    double T = 0;
    for (int b = 0; b < 3; ++b) {
      const Mat3 R_dot = rate(up.R[b], down.R[b], up2.R[b], down2.R[b]);
      const Mat3 W = at.R[b].transpose() * R_dot;  // body-frame angular velocity, skew
      const Vec3 w(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
      const Vec3 o_dot = at.R[b].transpose() * rate(up.o[b], down.o[b], up2.o[b], down2.o[b]);  // body frame
      if (b == 1) {
        Eigen::VectorXd V(6 + m);
        V << o_dot, 0.5 * w, x_dot.segment(eta(), m);
        T += 0.5 * V.dot(rig.boom->inertia.mass_matrix(x.segment(eta(), m)) * V);
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

// The joint's own coordinates at the scale of a rotation, a compliant
// pin's moves and tilts at a centimetre and ten milliradians.
double coordinate_size(const Reference& ref, int k) {
  if (ref.elastic(k)) return 0.002;
  return k > ref.j2() && k < ref.j2() + ref.joint_dof() ? 0.01 : 1.0;
}

class FlexibleSweep : public ::testing::TestWithParam<BoomJoint> {};

TEST_P(FlexibleSweep, RatesAndMomentumRatesMatchLagrangesEquations) {
  const Rig r = rig(0.0, {}, GetParam());
  const Scene& scene = r.file.scene;
  const Model& model = scene.model;
  const int m = r.boom->modes(), n = model.nv;
  ASSERT_EQ(n, 2 + model.joints[1].dof() + m);
  const Reference ref{r, model, m};
  Dynamics dynamics(scene);
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(n), x_dot(n);
  const Eigen::VectorXd scale = ref.scale();
  for (int k = 0; k < n; ++k) x[k] = coordinate_size(ref, k) * normal(random) / scale[k];
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
  // The reference's differences leave about 1e-7 (a formula's error shows as 1e-3 or more).
  for (int k = 0; k < n; ++k) EXPECT_NEAR(ydot[k] * scale[k], x_dot[k] * scale[k], 1e-6) << "rate " << k;

  // p' = dT/dq at fixed q' - K eta (and a compliant pin's -k x), by the
  // fourth-order central difference.
  for (int k = 0; k < n; ++k) {
    const double h = 1e-3 / scale[k];
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, k);
    double dp = (8 * (ref.kinetic(x + h * e, x_dot) - ref.kinetic(x - h * e, x_dot)) -
                 (ref.kinetic(x + 2 * h * e, x_dot) - ref.kinetic(x - 2 * h * e, x_dot))) /
                (12 * h);
    if (ref.elastic(k)) dp -= r.boom->stiffness[k - ref.eta()] * x[k];
    dp += ref.pin_force(x, k);
    EXPECT_NEAR(ydot[n + k], dp, 1e-5 * std::max(1.0, std::abs(dp))) << "momentum rate " << k;
  }
}

// The accelerations pass (loads, sensors) against the rates' change along
// the motion: w' by the fourth-order central difference of the sweep's
// rates over y +- h y', y +- 2h y' (the second-order one left 5e-6 of the
// largest acceleration: the stiffest modes ring at 1e5 rad/s).
TEST_P(FlexibleSweep, AccelerationsAreTheRatesRate) {
  const Rig r = rig(0.0, {}, GetParam());
  const Model& model = r.file.scene.model;
  const Reference ref{r, model, r.boom->modes()};
  Dynamics dynamics(r.file.scene);
  const int n = model.nv;
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  std::vector<double> y(dynamics.size()), ydot(dynamics.size()), w_dot(n);
  for (int k = 0; k < n; ++k)
    y[k] = (ref.elastic(k) ? 0.05 : 1.0) * coordinate_size(ref, k) * normal(random), y[n + k] = 0.1 * normal(random);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  const double h = 1e-7;
  const auto rates_at = [&](double s) {
    std::vector<double> moved(dynamics.size()), f(dynamics.size());
    for (int k = 0; k < dynamics.size(); ++k) moved[k] = y[k] + s * h * ydot[k];
    EXPECT_TRUE(dynamics.rhs(0, moved.data(), f.data()));
    return f;
  };
  const std::vector<double> up = rates_at(1), down = rates_at(-1), up2 = rates_at(2), down2 = rates_at(-2);
  ASSERT_TRUE(dynamics.rigid_accelerations(y.data(), ydot.data(), w_dot.data()));
  double largest = 0;
  for (int k = 0; k < n; ++k) largest = std::max(largest, std::abs(w_dot[k]));
  for (int k = 0; k < n; ++k)
    EXPECT_NEAR(w_dot[k], (8 * (up[k] - down[k]) - (up2[k] - down2[k])) / (12 * h), 1e-6 * largest)
        << "coordinate " << k;
}

// A free run through the whole solver: without damping the energy stays
// (kinetic, and the elastic energy the modes store as they ring); with
// modal damping what the modes dissipate balances its loss.
TEST_P(FlexibleSweep, ARunKeepsItsEnergyBalance) {
  for (double zeta : {0.0, 0.02}) {
    Rig r = rig(zeta, {2.0, -1.5, 3.0}, GetParam());
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

const char* kind_name(BoomJoint kind) {
  const char* names[] = {"Revolute", "Universal", "Compliant"};
  return names[static_cast<int>(kind)];
}
std::string joint_name(const ::testing::TestParamInfo<BoomJoint>& info) { return kind_name(info.param); }
// How gtest (and ctest's test names) show a kind.
void PrintTo(BoomJoint kind, std::ostream* os) { *os << kind_name(kind); }

INSTANTIATE_TEST_SUITE_P(BoomJoints, FlexibleSweep,
                         ::testing::Values(BoomJoint::revolute, BoomJoint::universal, BoomJoint::compliant),
                         joint_name);

// The joints whose coordinates are not their rates' integrals (a
// quaternion's): a free-floating flexible boom with a rigid tip on its end
// node and a rigid body on a ball joint at its root (a child on the frame
// itself, not on a node: the bias pass once dropped what it carried, and
// this run drifted 1-2 % in momentum), and a rigid bus with the flexible
// boom on a ball joint. Nothing acts from outside: the momentum holds (about
// the deformed bodies' centre of mass); undamped, the energy holds while
// the modes ring.
void expect_free_run_conserves(SceneBuilder& b, double least_elastic) {
  SceneFile file = b.build();
  Scene& scene = file.scene;
  scene.run.t_end = 2.0;
  scene.run.rtol = 1e-9;
  const RunResult run = simulate(scene, scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  const RunSummary::FreeBus bus = summarize_free_bus(scene.model, run.trajectory);
  EXPECT_LT(bus.linear_momentum_drift, 20 * scene.run.rtol);
  EXPECT_LT(bus.angular_momentum_drift, 20 * scene.run.rtol);
  const EnergyParts& first = run.trajectory.samples.front().energy;
  EXPECT_NEAR(run.trajectory.samples.back().energy.balance(), first.balance(), 1e-6 * first.total());
  double elastic = 0;
  for (const Sample& s : run.trajectory.samples) elastic = std::max(elastic, s.energy.springs);
  EXPECT_GT(elastic, least_elastic * first.total()) << "the modes ring";
}

Joint ball(const std::string& name, const Vec3& parent_point) {
  return Joint{name, JointType::spherical, Vec3::UnitX(), Vec3::UnitY(), parent_point, Vec3::Zero()};
}

TEST(FlexibleJoints, AFreeFloatingFlexibleBoomKeepsItsMomentumAndEnergy) {
  SceneBuilder b("free flexible boom");
  b.free_base(flexible_boom());
  b.body(rigid("tip", 0.7, Vec3(0.15, 0.02, 0.01), Vec3(0.004, 0.006, 0.005)), "boom",
         Joint{"j3", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3(1.2, 0, 0), Vec3(-0.05, 0, 0)});
  b.body(rigid("knob", 1.1, Vec3(0.05, 0.03, -0.02), Vec3(0.01, 0.02, 0.015)), "boom", ball("root", Vec3::Zero()));
  b.initial_rate("boom", {0.05, -0.1, 0.02, 0.3, -0.4, 0.5});
  b.initial_rate("j3", {1.0});
  b.initial_rate("root", {-0.5, 0.3, 0.2});
  expect_free_run_conserves(b, 1e-6);
}

TEST(FlexibleJoints, ABoomOnABallJointOfAFreeBusKeepsItsMomentumAndEnergy) {
  SceneBuilder b("flexible boom on a ball joint");
  b.free_base(rigid("bus", 20.0, Vec3(0.02, -0.01, 0.03), Vec3(2.0, 2.5, 3.0)));
  b.body(flexible_boom(), "bus", ball("root", Vec3(0.5, 0, 0)));
  b.body(rigid("tip", 0.7, Vec3(0.15, 0.02, 0.01), Vec3(0.004, 0.006, 0.005)), "boom",
         Joint{"j3", JointType::revolute, Vec3::UnitZ(), Vec3::UnitY(), Vec3(1.2, 0, 0), Vec3(-0.05, 0, 0)});
  b.initial_rate("bus", {0.0, 0.1, 0.0, 0.2, -0.1, 0.3});
  b.initial_rate("root", {1.5, -2.5, 2.0});
  b.initial_rate("j3", {-3.0});
  expect_free_run_conserves(b, 1e-6);
}

// A compliant hinge under the FE boom (examples/fem/magnetometer_boom.yaml)
// approaches the rigid hinge as its pin stiffens: the hinge angle's largest
// difference over the swing falls as 1 / k (the pin's static give under
// the swing's loads).
TEST(FlexibleJoints, ACompliantHingeUnderAFlexibleBoomApproachesTheRigidOne) {
  const std::string path = std::string(UNFURL_SOURCE_DIR) + "/examples/fem/magnetometer_boom.yaml";
  const auto run_with = [&](std::vector<Override> overrides) {
    overrides.push_back({"run.t_end", "2"});
    overrides.push_back({"run.rtol", "1e-10"});
    overrides.push_back({"run.atol", "1e-12"});
    const Scene scene = read_scene_file(path, overrides).scene;
    RunResult run = simulate(scene, scene.run);
    EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
    return run;
  };
  const RunResult rigid = run_with({});
  const auto difference = [&](double k) {
    const RunResult pin = run_with({{"bodies.boom.joint.compliance", "{radial: " + std::to_string(k) +
                                                                          ", axial: " + std::to_string(k) +
                                                                          ", tilt: " + std::to_string(k / 100) + "}"}});
    double worst = 0;
    const std::size_t n = std::min(pin.trajectory.samples.size(), rigid.trajectory.samples.size());
    for (std::size_t s = 0; s < n; ++s)
      worst = std::max(worst, std::abs(pin.trajectory.samples[s].y[0] - rigid.trajectory.samples[s].y[0]));
    return worst;
  };
  const double soft = difference(1e6), stiff = difference(1e7);
  std::printf("compliant hinge against rigid: %.3g rad (k 1e6 N/m), %.3g rad (1e7)\n", soft, stiff);
  EXPECT_GT(soft, 1e-9);
  EXPECT_NEAR(stiff / soft, 0.1, 0.03);
}

}  // namespace
}  // namespace unfurl::sim
