// Loads: the joint reactions from the sweep's accelerations against closed
// forms and against an independent dense Newton-Euler computation, the
// element torques, and the peaks over the integrator's steps.
#include <gtest/gtest.h>

#include <cmath>


#include "dense_formulation.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A rod of mass m hanging from a revolute joint about x at the base origin,
// its centre of mass `arm` below the hinge along the body's -z.
sim::Scene rod(double gravity, double arm) {
  return sim::load_scene_text(R"(
name: rod
gravity: [0, 0, )" + std::to_string(gravity) +
                                  R"(]
bodies:
  - name: rod
    parent: base
    mass: 2.0
    com: [0, 0, )" + std::to_string(-arm) +
                                  R"(]
    inertia: [0.1, 0.1, 0.02]
    joint: {name: hinge, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
)",
                              "rod");
}

sim::Loads loads_at(const sim::Scene& scene, std::vector<double> y) {
  sim::Dynamics dynamics(scene);
  sim::Loads loads;
  EXPECT_TRUE(dynamics.loads(0, y.data(), loads));
  return loads;
}

TEST(Loads, PendulumHangingAtRestCarriesItsWeight) {
  const sim::Scene scene = rod(-9.81, 0.5);
  const sim::Vec6 reaction = loads_at(scene, {0.0, 0.0}).reaction[0];
  // The hinge pushes up with m g; the weight's moment about the hinge is zero.
  EXPECT_NEAR(reaction[0], 0, 1e-12);
  EXPECT_NEAR(reaction[1], 0, 1e-12);
  EXPECT_NEAR(reaction[2], 2.0 * 9.81, 1e-12);
  EXPECT_NEAR(reaction.tail<3>().norm(), 0, 1e-12);
}

TEST(Loads, PendulumHeldSidewaysCarriesWeightAndMoment) {
  // Turned by 90 degrees and at rest: the hinge carries the weight and, in
  // the same instant, the moment that is not yet angular acceleration. Its
  // axis component is the applied joint torque: zero.
  const sim::Scene scene = rod(-9.81, 0.5);
  const sim::Vec6 reaction = loads_at(scene, {M_PI / 2, 0.0}).reaction[0];
  EXPECT_NEAR(reaction[3], 0, 1e-12);  // about the hinge axis
  // Free fall of the centre of mass: a = J_hinge^-1 m g l, the hinge force
  // is m g minus the mass times that acceleration.
  const double J = 0.1 + 2.0 * 0.25, alpha = 2.0 * 9.81 * 0.5 / J;
  const double expected = 2.0 * 9.81 - 2.0 * alpha * 0.5;
  EXPECT_NEAR(reaction.head<3>().norm(), expected, 1e-10);
}

TEST(Loads, SpinningBodyCarriesItsCentripetalLoad) {
  // No gravity, turning at w about the hinge: the hinge pulls the centre of
  // mass inward with m w^2 r and carries no moment.
  const sim::Scene scene = rod(0, 0.5);
  const double w = 3.0, J = 0.1 + 2.0 * 0.25;
  const sim::Vec6 reaction = loads_at(scene, {0.3, J * w}).reaction[0];
  EXPECT_NEAR(reaction.head<3>().norm(), 2.0 * w * w * 0.5, 1e-10);
  // Pulling toward the hinge: along +z of the body (the com is at -z).
  EXPECT_NEAR(reaction[2], 2.0 * w * w * 0.5, 1e-10);
  EXPECT_NEAR(reaction.tail<3>().norm(), 0, 1e-10);
}

TEST(Loads, AxisComponentOfTheReactionIsTheJointTorque) {
  // The z-fold at a generic moving state with its latches engaged.
  const sim::Scene scene = test::scene_file("zfold");
  sim::Dynamics dynamics(scene);
  for (int l = 0; l < dynamics.latch_count(); ++l) dynamics.latch_state().engage(l);
  std::vector<double> y = dynamics.initial_state();
  for (std::size_t k = 0; k < y.size(); ++k) y[k] += 0.1 * std::sin(1.0 + k);
  sim::Loads loads;
  ASSERT_TRUE(dynamics.loads(0, y.data(), loads));
  const std::vector<sim::LoadColumn>& columns = dynamics.load_columns();
  for (int j = 0; j < scene.model.size(); ++j) {
    const sim::Vec3& axis = scene.model.joints[j].axis;
    EXPECT_NEAR(axis.dot(loads.reaction[j].tail<3>()), test::joint_element_torque(columns, loads, j), 1e-10) << j;
    EXPECT_NE(test::load_of(columns, loads, "latch_torque." + scene.model.joints[j].name), 0.0);
  }
}

class RandomTreeLoads : public ::testing::TestWithParam<int> {};

TEST_P(RandomTreeLoads, ReactionsMatchADenseNewtonEulerComputation) {
  // The test's own dense formulation: ddq from Mtilde ddq = p' - (dMtilde/dt)
  // dq, body accelerations from v = T A dq, then the joint wrenches
  // f = T^T (M a + v x* M v - F) (S^T f is each body's net wrench from its
  // joints). Time derivatives by central differences along dq.
  std::mt19937 rng(100 + GetParam());
  const sim::Scene scene = test::random_tree(rng, 1 + GetParam() % 12, false);
  const int n = scene.model.nq, N = scene.model.size();
  if (n == 0) GTEST_SKIP() << "only fixed joints";
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> y(2 * n), ydot(2 * n);
  for (int k = 0; k < n; ++k) y[k] = scene.q0[k], y[n + k] = 3 * U(rng);
  sim::Dynamics dynamics(scene);
  ASSERT_TRUE(dynamics.rhs(0, y.data(), ydot.data()));
  sim::Loads loads;
  dynamics.loads(0, y.data(), loads);

  const VectorXd q = Eigen::Map<VectorXd>(y.data(), n), dq = Eigen::Map<VectorXd>(ydot.data(), n);
  const VectorXd dp = Eigen::Map<VectorXd>(ydot.data() + n, n);
  const double h = 1e-5;
  const test::Dense d = test::dense_formulation(scene, q), plus = test::dense_formulation(scene, q + h * dq),
                    minus = test::dense_formulation(scene, q - h * dq);
  const VectorXd ddq = d.Mt.ldlt().solve(dp - (plus.Mt - minus.Mt) / (2 * h) * dq);
  const MatrixXd TA = d.ATTt.transpose();
  const VectorXd v = TA * dq;
  const VectorXd a = TA * ddq + (plus.ATTt - minus.ATTt).transpose() / (2 * h) * dq;
  VectorXd net(6 * N);
  for (int i = 0; i < N; ++i) {
    const sim::Body& b = scene.model.bodies[i];
    sim::Mat6 M = sim::Mat6::Zero();
    const sim::Mat3 J =
        b.inertia_com + b.mass * (b.com.squaredNorm() * sim::Mat3::Identity() - b.com * b.com.transpose());
    M.topLeftCorner<3, 3>() = b.mass * sim::Mat3::Identity();
    M.topRightCorner<3, 3>() = -b.mass * sim::skew(b.com);
    M.bottomLeftCorner<3, 3>() = b.mass * sim::skew(b.com);
    M.bottomRightCorner<3, 3>() = J;
    const sim::Vec6 vi = v.segment<6>(6 * i), h_i = M * vi;
    sim::Vec6 gyro;
    gyro.head<3>() = vi.tail<3>().cross(h_i.head<3>());
    gyro.tail<3>() = vi.head<3>().cross(h_i.head<3>()) + vi.tail<3>().cross(h_i.tail<3>());
    net.segment<6>(6 * i) = M * a.segment<6>(6 * i) + gyro;
  }
  const VectorXd f = d.T.transpose() * (net - test::body_forces(scene, q, true));
  double scale = 1;
  for (int i = 0; i < N; ++i) scale = std::max(scale, f.segment<6>(6 * i).norm());
  for (int i = 0; i < N; ++i) {
    sim::Vec6 expected = f.segment<6>(6 * i);
    expected.tail<3>() -= scene.model.joints[i].child_point.cross(expected.head<3>());
    EXPECT_LT((loads.reaction[i] - expected).norm(), 1e-6 * scale) << "joint " << i << " of " << N;
  }
}

INSTANTIATE_TEST_SUITE_P(UpTo12Bodies, RandomTreeLoads, ::testing::Range(0, 20));

TEST(Loads, PeaksDoNotDependOnTheSampling) {
  // The peaks follow the integrator's steps, which do not depend on the
  // sampling interval: the same to the last bit.
  const sim::Scene coarse = test::scene_file("zfold", {{"run.sample", "0.5"}});
  const sim::Scene fine = test::scene_file("zfold", {{"run.sample", "0.001"}});
  const sim::RunSummary a = sim::summarize(coarse, sim::simulate(coarse, coarse.run));
  const sim::RunSummary b = sim::summarize(fine, sim::simulate(fine, fine.run));
  ASSERT_EQ(a.peak_latch_torque.size(), 4u);
  for (std::size_t l = 0; l < a.peak_latch_torque.size(); ++l) {
    EXPECT_EQ(a.peak_latch_torque[l].peak.value, b.peak_latch_torque[l].peak.value);
    EXPECT_EQ(a.peak_latch_torque[l].peak.t, b.peak_latch_torque[l].peak.t);
  }
  for (std::size_t j = 0; j < a.peak_hinge_moment.size(); ++j)
    EXPECT_EQ(a.peak_hinge_moment[j].peak.value, b.peak_hinge_moment[j].peak.value);
}

TEST(Loads, LatchPeakIsAboveEverySampledValue) {
  // The coarse samples miss the shock's peak; the steps do not.
  const sim::Scene scene = test::scene_file("zfold", {{"run.sample", "0.1"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const sim::RunSummary s = sim::summarize(scene, run);
  for (std::size_t l = 0; l < scene.latches().size(); ++l) {
    double sampled = 0;
    for (const sim::Sample& x : run.trajectory.samples)
      sampled = std::max(sampled,
                         std::abs(test::load_of(run.trajectory.load_columns, x.loads,
                                                "latch_torque." + scene.model.joints[scene.latches()[l]->joint].name)));
    EXPECT_GE(s.peak_latch_torque[l].peak.value, sampled);
    EXPECT_GT(s.peak_latch_torque[l].peak.value, 1.0);  // N m: a real shock
  }
}

TEST(Loads, LoopForcesHoldThePantographTogether) {
  // At the start the springs pull the chains apart at the cross pivots; the
  // loop forces are what keeps the split bodies on their images, so they
  // are not zero, and the regulator state has not wound up.
  const sim::Scene scene = test::scene_file("pantograph");
  sim::Dynamics dynamics(scene);
  std::vector<double> y = dynamics.initial_state();
  sim::Loads loads;
  dynamics.loads(0, y.data(), loads);
  ASSERT_EQ(static_cast<int>(loads.loop_force.size()), dynamics.layout().m);
  double largest = 0;
  for (double f : loads.loop_force) largest = std::max(largest, std::abs(f));
  EXPECT_GT(largest, 1e-3);
}

}  // namespace
}  // namespace unfurl
