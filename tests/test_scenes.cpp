// The reference scenes beyond the pantograph: the exact stowed start and the
// z-fold.
#include <gtest/gtest.h>

#include "scene_generators.hpp"
#include "summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

TEST(PantographStowed, RunsToTheEndAndReportsWhichJointsLatched) {
  const Scene scene = test::scene_file("pantograph_stowed");
  const RunResult run = simulate(scene, scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  EXPECT_DOUBLE_EQ(run.trajectory.t_end(), 20.0);
  const RunSummary s = summarize(scene, run);
  // Every latch is accounted for: latched with a time, or listed unlatched.
  EXPECT_EQ(s.latch_times.size() + s.unlatched.size(), scene.latches.size());
  EXPECT_LT(s.max_closure_m, 1e-5);
  std::printf("stowed start: %zu of 8 latched;", s.latch_times.size());
  for (const auto& [joint, t] : s.latch_times) std::printf(" %s@%.4f", joint.c_str(), t);
  std::printf("\n");
}

TEST(Zfold, DeploysAndLatches) {
  const Scene scene = test::scene_file("zfold");
  const RunResult run = simulate(scene, scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  EXPECT_EQ(run.trajectory.events.size(), 4u);
  // Deployed: every joint ends near q = 0, held by its latch.
  for (double q : std::vector<double>(run.trajectory.samples.back().y.begin(),
                                      run.trajectory.samples.back().y.begin() + 4))
    EXPECT_LT(std::abs(q), 0.01);
  // A tree: no loop states at all.
  EXPECT_EQ(run.trajectory.layout.m, 0);
}

TEST(Zfold, EveryIntegratorDeploysIt) {
  const Scene scene = test::scene_file("zfold");
  const RunResult reference = simulate(scene, scene.run);
  for (IntegratorKind kind : all_integrators()) {
    RunSettings settings = scene.run;
    settings.integrator = kind;
    settings.dt = 1e-4;
    const RunResult run = simulate(scene, settings);
    ASSERT_EQ(run.status, RunStatus::finished) << integrator_name(kind) << ": " << describe(run.failure);
    ASSERT_EQ(run.trajectory.events.size(), 4u) << integrator_name(kind);
    for (std::size_t e = 0; e < 4; ++e)
      EXPECT_NEAR(run.trajectory.events[e].t, reference.trajectory.events[e].t, 1e-4) << integrator_name(kind);
  }
}

}  // namespace
}  // namespace unfurl

namespace unfurl {
namespace {

// The generator with 3 stages (3 panels) writes the reference scenes.
void expect_same_mechanism(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.model.size(), b.model.size());
  for (int i = 0; i < a.model.size(); ++i) {
    const Body &x = a.model.bodies[i], &y = b.model.bodies[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_DOUBLE_EQ(x.mass, y.mass) << x.name;
    EXPECT_TRUE(x.inertia_com.isApprox(y.inertia_com, 1e-15)) << x.name;
    const Joint &j = a.model.joints[i], &k = b.model.joints[i];
    EXPECT_EQ(j.name, k.name);
    EXPECT_EQ(a.model.parent[i], b.model.parent[i]) << x.name;
    EXPECT_TRUE(j.parent_point.isApprox(k.parent_point, 1e-15) || (j.parent_point - k.parent_point).norm() < 1e-15)
        << j.name;
    EXPECT_TRUE((j.child_point - k.child_point).norm() < 1e-15) << j.name;
  }
  ASSERT_EQ(a.springs.size(), b.springs.size());
  for (std::size_t s = 0; s < a.springs.size(); ++s) {
    EXPECT_EQ(a.springs[s].joint, b.springs[s].joint);
    EXPECT_DOUBLE_EQ(a.springs[s].free_position, b.springs[s].free_position);
    EXPECT_DOUBLE_EQ(a.springs[s].stiffness, b.springs[s].stiffness);
    EXPECT_DOUBLE_EQ(a.springs[s].damping, b.springs[s].damping);
  }
  ASSERT_EQ(a.latches.size(), b.latches.size());
  ASSERT_EQ(a.loops.size(), b.loops.size());
  for (std::size_t l = 0; l < a.loops.size(); ++l) {
    EXPECT_EQ(a.loops[l].body, b.loops[l].body);
    EXPECT_EQ(a.loops[l].image, b.loops[l].image);
  }
  ASSERT_EQ(a.q0.size(), b.q0.size());
  for (std::size_t c = 0; c < a.q0.size(); ++c) EXPECT_DOUBLE_EQ(a.q0[c], b.q0[c]) << "coordinate " << c;
}

TEST(Generator, ThreeStagePantographIsTheReferenceScene) {
  expect_same_mechanism(load_scene_text(generate_pantograph(3), "generated"), test::scene_file("pantograph"));
}

TEST(Generator, ThreePanelZfoldIsTheReferenceScene) {
  expect_same_mechanism(load_scene_text(generate_zfold(3), "generated"), test::scene_file("zfold"));
}

TEST(Generator, LargerScenesLoadAndClose) {
  // The loader checks the loops close at the initial state.
  EXPECT_EQ(load_scene_text(generate_pantograph(8), "generated").loops.size(), 8u);
  EXPECT_EQ(load_scene_text(generate_zfold(20), "generated").model.size(), 21);
  EXPECT_EQ(load_scene_text(generate_chain(50), "generated").model.size(), 50);
}

TEST(LargeArray, TwentyStagePantographStaysClosedWithSparseGainsAndKrylov) {
  // 62 bodies, 60 loop components: beyond the dense solvers, so the gains
  // come from the sparse closure solver and BDF's Newton systems from GMRES.
  const Scene scene = load_scene_text(generate_pantograph(20), "pantograph_20", {{"run.t_end", "1"}});
  const RunResult run = simulate(scene, scene.run);
  ASSERT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  EXPECT_GT(run.stats.linear_iterations, 0);
  EXPECT_EQ(run.stats.jacobian_evals, 0);
  const RunSummary s = summarize(scene, run);
  EXPECT_LT(s.max_closure_m, 1e-6);
  // The array opens: the root joint has moved toward deployment.
  const Sample& last = run.trajectory.samples.back();
  EXPECT_LT(std::abs(test::q_of(scene, last, "j1")), std::abs(scene.q0[0]) - 1e-4);
}

}  // namespace
}  // namespace unfurl
