// A free-floating bus (body 0 on a free joint): nothing acts from outside,
// so the system's linear and angular momentum are conserved (to a bound
// tied to rtol) and its centre of mass stays put, while the bus turns in
// reaction to the deploying array; a bus made very heavy holds still and
// the array deploys as on a fixed base; the quaternion keeps its norm.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/momentum.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

struct FreeRun {
  sim::Scene scene;
  sim::RunResult result;
  sim::RunSummary::FreeBus bus;
};

FreeRun run_free(const std::string& name, const std::vector<sim::Override>& overrides = {}) {
  FreeRun r{sim::load_builtin_scene(name, overrides), {}, {}};
  r.result = sim::simulate(r.scene, r.scene.run);
  EXPECT_EQ(r.result.status, sim::RunStatus::finished) << sim::describe(r.result.failure);
  r.bus = sim::summarize_free_bus(r.scene.model, r.result.trajectory);
  return r;
}

// The system's centre of mass at a sample.
sim::Vec3 centre_of_mass(const sim::Model& model, const sim::Sample& s) {
  std::vector<sim::Pose> poses;
  sim::body_poses(model, s.y.data(), poses);
  sim::Vec3 moment = sim::Vec3::Zero();
  double mass = 0;
  for (int i = 0; i < model.size(); ++i) {
    moment += model.bodies[i].mass * poses[i].to_base(model.bodies[i].com);
    mass += model.bodies[i].mass;
  }
  return moment / mass;
}

// Linear and angular momentum drift within 20 rtol of the sums of the
// bodies' own momenta; the centre of mass within 10 nm; the bus turned.
void expect_conserved(const FreeRun& r, double least_turn) {
  const double rtol = r.scene.run.rtol;
  std::printf("%s: momentum drift %.3g (linear), %.3g (angular) at rtol %g; bus turned %.4g rad, peak rate %.4g rad/s\n",
              r.scene.name.c_str(), r.bus.linear_momentum_drift, r.bus.angular_momentum_drift, rtol,
              r.bus.final_attitude_change, r.bus.peak_rate);
  EXPECT_LT(r.bus.linear_momentum_drift, 20 * rtol);
  EXPECT_LT(r.bus.angular_momentum_drift, 20 * rtol);
  EXPECT_GT(r.bus.final_attitude_change, least_turn);
  const sim::Trajectory& tr = r.result.trajectory;
  const sim::Vec3 c0 = centre_of_mass(r.scene.model, tr.samples.front());
  double moved = 0;
  for (const sim::Sample& s : tr.samples) moved = std::max(moved, (centre_of_mass(r.scene.model, s) - c0).norm());
  EXPECT_LT(moved, 1e-8) << "the centre of mass moved";  // the positions' integration error: 2.4e-9 and 1.2e-9 m
  // The bus quaternion's norm: a first integral of q' = q (x) (0, w) / 2.
  const int c = r.scene.model.first_position[0].value + 3;
  for (const sim::Sample& s : tr.samples)
    ASSERT_NEAR(Eigen::Vector4d(s.y[c], s.y[c + 1], s.y[c + 2], s.y[c + 3]).norm(), 1.0, 1e-6) << "t = " << s.t;
}

// The bus's free joint joins it to nothing: it is no hinge, and neither the
// summary's hinge peaks nor the loads' columns list it (they listed zeros).
TEST(FreeFloating, TheBusIsNoHingeInTheLoads) {
  const sim::Scene scene = sim::load_builtin_scene("zfold_free", {{"run.t_end", "1"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const sim::RunSummary s = sim::summarize(scene, run);
  ASSERT_EQ(s.peak_hinge_force.size(), 4u);
  for (const auto& p : s.peak_hinge_force) EXPECT_NE(p.joint, "bus");
  EXPECT_EQ(scene.model.joints[0].name, "bus");
}

TEST(FreeFloating, ZfoldConservesMomentumWhileTheBusTurns) { expect_conserved(run_free("zfold_free"), 0.1); }

TEST(FreeFloating, PantographConservesMomentumWhileTheBusTurns) {
  expect_conserved(run_free("pantograph_free"), 1e-3);
}

TEST(FreeFloating, ASpinningBusKeepsItsMomentum) {
  // Released spinning and drifting: the momentum is not zero, and its
  // conservation is the integrator's doing, not a zero staying zero.
  const FreeRun r = run_free("zfold_free", {{"initial.dq.bus", "[0.01, 0.02, 0, 0.02, -0.03, 0.05]"}});
  const sim::Sample& first = r.result.trajectory.samples.front();
  EXPECT_GT(first.momentum.angular.norm(), 1.0);
  std::printf("spinning zfold_free: |L| = %.4g N m s\n", first.momentum.angular.norm());
  EXPECT_LT(r.bus.linear_momentum_drift, r.scene.run.rtol);
  EXPECT_LT(r.bus.angular_momentum_drift, r.scene.run.rtol);
}

TEST(FreeFloating, AVeryHeavyBusHoldsStillAndTheWingDeploysAsOnAFixedBase) {
  const std::vector<sim::Override> heavy{{"base.mass", "1e9"}, {"base.inertia", "[1e9, 1e9, 1e9]"}};
  const FreeRun r = run_free("zfold_free", heavy);
  const sim::Scene fixed = sim::load_builtin_scene("zfold");
  const sim::RunResult reference = sim::simulate(fixed, fixed.run);
  ASSERT_EQ(reference.status, sim::RunStatus::finished);
  const sim::Trajectory &a = r.result.trajectory, &b = reference.trajectory;
  ASSERT_EQ(a.samples.size(), b.samples.size());
  double worst = 0;
  for (std::size_t k = 0; k < a.samples.size(); ++k)
    for (const char* joint : {"j1", "j2", "j3", "j4"})
      worst = std::max(worst, std::abs(test::q_of(r.scene, a.samples[k], joint) - test::q_of(fixed, b.samples[k], joint)));
  std::printf("heavy bus: largest joint angle difference from the fixed base %.3g rad; bus turned %.3g rad\n", worst,
              r.bus.final_attitude_change);
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(r.bus.final_attitude_change, 1e-7);
}

}  // namespace
}  // namespace unfurl
