// The regularization the regulator chooses when a scene sets none
// (Regulator::automatic_regularization): ten times the weakest loop mode at
// the start, between the finest and the coarsest; exactly redundant
// directions left out; dimensionless; a scene's own value kept.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "unfurl/studies/scene_scaling.hpp"

namespace unfurl {
namespace {

double chosen(const sim::Scene& scene) { return sim::Dynamics(scene).regulator()->regularization(); }

TEST(AutomaticRegularization, TheReferenceScenesKeepTheCoarsest) {
  // Their weakest modes lie at 1.7e-6 (pantograph) and above of the largest
  // (1.4e-3 on pantograph_flexible). The stowed pantograph starts at its
  // branch point, where three modes are zeros at round-off (1e-17): lost,
  // not weak, so they do not count.
  for (const char* name : {"pantograph", "pantograph_free", "pantograph_stowed", "pantograph_flexible", "fourbar"})
    EXPECT_EQ(chosen(test::scene_file(name)), sim::Regulator::kCoarsestRegularization) << name;
}

TEST(AutomaticRegularization, TenTimesTheWeakestModeOfALongArray) {
  // The 10-stage array's 30 components fit the dense W: its spectrum from
  // the dense passes, not the products the regulator's own choice uses.
  const sim::Scene scene = studies::generate_pantograph(10).scene;
  sim::Dynamics dynamics(scene);
  sim::Regulator& regulator = *dynamics.regulator();
  sim::Sweep sweep(scene.model);
  sweep.set_configuration(scene.q0.data());
  const int m = regulator.size();
  Eigen::VectorXd S(m);
  for (int c = 0; c < m; ++c) S[c] = 1 / regulator.component_scale(c);
  const Eigen::MatrixXd SWS = S.asDiagonal() * Eigen::MatrixXd(regulator.mobility(sweep)) * S.asDiagonal();
  const Eigen::VectorXd w = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(SWS).eigenvalues();
  const double weakest = w[0] / w[m - 1];
  ASSERT_GT(weakest, sim::Regulator::kRedundantMode);  // no redundant direction in this one
  const double expected = sim::Regulator::kRegularizationPerWeakestMode * weakest;
  ASSERT_GT(expected, sim::Regulator::kFinestRegularization);
  ASSERT_LT(expected, sim::Regulator::kCoarsestRegularization);
  EXPECT_NEAR(regulator.regularization(), expected, 1e-6 * expected);
}

TEST(AutomaticRegularization, IsDimensionless) {
  const sim::SceneFile original = studies::generate_pantograph(10);
  const double base = chosen(original.scene);
  for (const auto& [L, M] : {std::pair{1e-3, 1e-6}, std::pair{1e1, 1e3}})
    EXPECT_NEAR(chosen(studies::scale_scene(original, L, M).scene), base, 1e-6 * base) << L << " " << M;
}

TEST(AutomaticRegularization, ASceneKeepsItsOwnAndTheRunSaysWhich) {
  const sim::Scene set = test::scene_file("pantograph", {{"regulator.regularization", "3e-7"}, {"run.t_end", "0.01"}});
  EXPECT_EQ(chosen(set), 3e-7);
  const sim::RunResult run = sim::simulate(set, set.run);
  ASSERT_TRUE(run.closure);
  EXPECT_EQ(run.closure->regularization, 3e-7);
  EXPECT_FALSE(run.closure->regularization_automatic);
  const sim::Scene automatic =
      test::scene_file("pantograph", {{"regulator.regularization", "auto"}, {"run.t_end", "0.01"}});
  const sim::RunResult automatic_run = sim::simulate(automatic, automatic.run);
  ASSERT_TRUE(automatic_run.closure);
  EXPECT_EQ(automatic_run.closure->regularization, sim::Regulator::kCoarsestRegularization);
  EXPECT_TRUE(automatic_run.closure->regularization_automatic);
  const sim::Scene paper = test::scene_file("pantograph", {{"regulator.gains", "paper"}, {"run.t_end", "0.01"}});
  EXPECT_EQ(chosen(paper), 0);  // the paper's diagonal gains have no delta
}

}  // namespace
}  // namespace unfurl
