// Scenes of any size from the generators: the three-stage ones are the
// reference scenes, larger ones load, close and run with the sparse closure
// solver and GMRES.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "closure_check.hpp"
#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

using Eigen::VectorXd;
using test::expect_closure_solve_matches_dense;

// The generator with 3 stages (3 panels) writes the reference scenes.
void expect_same_mechanism(const sim::Scene& a, const sim::Scene& b) {
  ASSERT_EQ(a.model.size(), b.model.size());
  for (int i = 0; i < a.model.size(); ++i) {
    const sim::Body &x = a.model.bodies[i], &y = b.model.bodies[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_DOUBLE_EQ(x.mass, y.mass) << x.name;
    EXPECT_TRUE(x.inertia_com.isApprox(y.inertia_com, 1e-15)) << x.name;
    const sim::Joint &j = a.model.joints[i], &k = b.model.joints[i];
    EXPECT_EQ(j.name, k.name);
    EXPECT_EQ(a.model.parent[i], b.model.parent[i]) << x.name;
    EXPECT_TRUE(j.parent_point.isApprox(k.parent_point, 1e-15) || (j.parent_point - k.parent_point).norm() < 1e-15)
        << j.name;
    EXPECT_TRUE((j.child_point - k.child_point).norm() < 1e-15) << j.name;
  }
  const std::vector<const sim::JointSpring*> springs_a = a.elements_of<sim::JointSpring>(),
                                             springs_b = b.elements_of<sim::JointSpring>();
  ASSERT_EQ(springs_a.size(), springs_b.size());
  for (std::size_t s = 0; s < springs_a.size(); ++s) {
    EXPECT_EQ(springs_a[s]->joint, springs_b[s]->joint);
    EXPECT_DOUBLE_EQ(springs_a[s]->free_position, springs_b[s]->free_position);
    EXPECT_DOUBLE_EQ(springs_a[s]->stiffness, springs_b[s]->stiffness);
    EXPECT_DOUBLE_EQ(springs_a[s]->damping, springs_b[s]->damping);
  }
  ASSERT_EQ(a.latches().size(), b.latches().size());
  ASSERT_EQ(a.loops.size(), b.loops.size());
  for (std::size_t l = 0; l < a.loops.size(); ++l) {
    EXPECT_EQ(a.loops[l].body, b.loops[l].body);
    EXPECT_EQ(a.loops[l].image, b.loops[l].image);
  }
  ASSERT_EQ(a.q0.size(), b.q0.size());
  for (std::size_t c = 0; c < a.q0.size(); ++c) EXPECT_DOUBLE_EQ(a.q0[c], b.q0[c]) << "coordinate " << c;
}

TEST(Generator, ThreeStagePantographIsTheReferenceScene) {
  expect_same_mechanism(studies::generate_pantograph(3).scene, test::scene_file("pantograph"));
}

TEST(Generator, ThreePanelZfoldIsTheReferenceScene) {
  expect_same_mechanism(studies::generate_zfold(3).scene, test::scene_file("zfold"));
}

TEST(Generator, LargerScenesLoadAndClose) {
  // The loader checks the loops close at the initial state.
  EXPECT_EQ(studies::generate_pantograph(8).scene.loops.size(), 8u);
  EXPECT_EQ(studies::generate_zfold(20).scene.model.size(), 21);
  EXPECT_EQ(studies::generate_chain(50).scene.model.size(), 50);
}

TEST(LargeArray, TwentyStagePantographStaysClosedWithSparseGainsAndKrylov) {
  // 62 bodies, 60 loop components: beyond the dense solvers, so the gains
  // come from the sparse closure solver and BDF's Newton systems from GMRES.
  const sim::Scene scene = sim::apply_overrides(studies::generate_pantograph(20), {{"run.t_end", "1"}}).scene;
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_GT(run.stats.linear_iterations, 0);
  EXPECT_EQ(run.stats.jacobian_evals, 0);
  const sim::RunSummary s = sim::summarize(scene, run);
  EXPECT_LT(s.max_closure_gap, 1e-6);
  // The array opens: the root joint has moved toward deployment.
  const sim::Sample& last = run.trajectory.samples.back();
  EXPECT_LT(std::abs(test::q_of(scene, last, "j1")), std::abs(scene.q0[0]) - 1e-4);
}

TEST(ClosureSolver, SparseOnTenLoops) {
  const sim::Scene scene = studies::generate_pantograph(10).scene;
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.5 * scene.q0[k];
  expect_closure_solve_matches_dense(scene, sim::ClosureSolverKind::sparse, q, 1e-5);
}

}  // namespace
}  // namespace unfurl
