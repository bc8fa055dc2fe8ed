// Scenes of any size from the generators: the three-stage ones are the
// reference scenes, larger ones load, close and run with the sparse closure
// solver and GMRES.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "closure_check.hpp"
#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/elements/bushing.hpp"
#include "unfurl/sim/elements/joint_compliance.hpp"
#include "unfurl/sim/elements/joint_limit.hpp"
#include "unfurl/sim/scene_file.hpp"
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

TEST(Generator, ThreeStageCompliantPantographIsTheReferenceScene) {
  const sim::Scene generated =
      studies::generate_pantograph(3, studies::CrossPivots::compliant, studies::Snubbers::none).scene;
  const sim::Scene reference = test::scene_file("pantograph_compliant");
  expect_same_mechanism(generated, reference);
  const std::vector<const sim::Bushing*> a = generated.elements_of<sim::Bushing>(),
                                         b = reference.elements_of<sim::Bushing>();
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k]->name, b[k]->name);
    EXPECT_EQ(a[k]->a.body, b[k]->a.body);
    EXPECT_EQ(a[k]->b.body, b[k]->b.body);
    EXPECT_TRUE((a[k]->a.point - b[k]->a.point).norm() < 1e-15) << a[k]->name;
    EXPECT_TRUE((a[k]->b.point - b[k]->b.point).norm() < 1e-15) << a[k]->name;
    EXPECT_TRUE((a[k]->stiffness - b[k]->stiffness).norm() == 0) << a[k]->name;
    EXPECT_TRUE((a[k]->damping - b[k]->damping).norm() == 0) << a[k]->name;
  }
}

TEST(Generator, CompliantPantographsAreTreesWithAPinPerStage) {
  const sim::Scene scene = studies::generate_pantograph(7, studies::CrossPivots::compliant).scene;
  EXPECT_EQ(scene.model.size(), 2 * 7 + 2);
  EXPECT_TRUE(scene.loops.empty());
  EXPECT_EQ(scene.elements_of<sim::Bushing>().size(), 7u);
  // Every pin starts unloaded: its two points coincide on the stowed
  // lazy-tongs path.
  sim::Dynamics dynamics(scene);
  std::vector<double> y = dynamics.initial_state();
  sim::Loads loads;
  ASSERT_TRUE(dynamics.loads(0, y.data(), loads));
  int pin_columns = 0;
  for (std::size_t c = 0; c < dynamics.load_columns().size(); ++c)
    if (dynamics.load_columns()[c].name.rfind("bushing_force.", 0) == 0) {
      ++pin_columns;
      EXPECT_LT(std::abs(loads.element[c]), 1e-6) << dynamics.load_columns()[c].name;
    }
  EXPECT_EQ(pin_columns, 3 * 7);
}

TEST(Generator, ThreeStageFlexiblePantographIsTheReferenceScene) {
  const sim::Scene generated = studies::generate_flexible_pantograph(3, studies::Snubbers::none).scene;
  const sim::Scene reference = test::scene_file("pantograph_flexible");
  expect_same_mechanism(generated, reference);
  int plates = 0;
  for (int i = 0; i < generated.model.size(); ++i) {
    const auto &a = generated.model.bodies[i].flexible, &b = reference.model.bodies[i].flexible;
    ASSERT_EQ(a == nullptr, b == nullptr) << generated.model.bodies[i].name;
    if (!a) continue;
    ++plates;
    ASSERT_TRUE(a->plate && b->plate);
    const sim::flexible::PlateBodySpec &x = *a->plate, &y = *b->plate;
    EXPECT_EQ(x.plate.length_x, y.plate.length_x);
    EXPECT_EQ(x.plate.length_y, y.plate.length_y);
    EXPECT_EQ(x.plate.bending_stiffness, y.plate.bending_stiffness);
    EXPECT_EQ(x.plate.poisson, y.plate.poisson);
    EXPECT_DOUBLE_EQ(x.plate.mass_per_area, y.plate.mass_per_area);
    EXPECT_EQ(x.plate.elements_x, y.plate.elements_x);
    EXPECT_EQ(x.plate.elements_y, y.plate.elements_y);
    EXPECT_EQ(x.corner, y.corner);
    EXPECT_EQ(x.root_edge, y.root_edge);
    EXPECT_EQ(x.hinge_lines, y.hinge_lines);
    EXPECT_EQ(x.normal_modes, y.normal_modes);
    ASSERT_EQ(x.damping.bands.size(), y.damping.bands.size());
    for (std::size_t k = 0; k < x.damping.bands.size(); ++k) {
      EXPECT_EQ(x.damping.bands[k].up_to_hz, y.damping.bands[k].up_to_hz);
      EXPECT_EQ(x.damping.bands[k].ratio, y.damping.bands[k].ratio);
    }
    // The same nodes, in the same order: the same reduction.
    EXPECT_EQ(x.attachments, y.attachments) << generated.model.bodies[i].name;
    EXPECT_EQ(a->modes(), b->modes());
    EXPECT_TRUE(a->frequency_hz.isApprox(b->frequency_hz, 1e-12));
  }
  EXPECT_EQ(plates, 6);
  const std::vector<const sim::JointCompliance*> a = generated.elements_of<sim::JointCompliance>(),
                                                 b = reference.elements_of<sim::JointCompliance>();
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k]->joint, b[k]->joint);
    EXPECT_EQ(a[k]->stiffnesses(), b[k]->stiffnesses());
    EXPECT_EQ(a[k]->dampings(), b[k]->dampings());
  }
  ASSERT_EQ(generated.sensors.size(), 1u);
  EXPECT_EQ(generated.sensors[0].body, reference.sensors[0].body);
  EXPECT_EQ(generated.sensors[0].point, reference.sensors[0].point);
  EXPECT_EQ(generated.regulator.v_max, reference.regulator.v_max);
}

TEST(Generator, FlexiblePantographsCloseTheirLoopsThroughThePlates) {
  const sim::Scene scene = studies::generate_flexible_pantograph(6).scene;
  EXPECT_EQ(scene.model.size(), 4 * 6 + 2);
  EXPECT_EQ(scene.loops.size(), 6u);
  EXPECT_EQ(scene.elements_of<sim::JointCompliance>().size(), 6u);
  // A snubber under each hinge of the two chains, as on the compliant array.
  EXPECT_EQ(scene.elements_of<sim::JointLimit>().size(), 2u * 6 + 2);
  const sim::Scene bare = studies::generate_flexible_pantograph(6, studies::Snubbers::none).scene;
  EXPECT_TRUE(bare.elements_of<sim::JointLimit>().empty());
  int plates = 0;
  for (const sim::Body& body : scene.model.bodies) plates += body.flexible != nullptr;
  EXPECT_EQ(plates, 12);
  // Each panel weighs the rigid array's: chain A's plate and its pin's two
  // halves, chain B's plate.
  const sim::Scene rigid = studies::generate_pantograph(6).scene;
  double mass = 0, rigid_mass = 0;
  for (const sim::Body& body : scene.model.bodies) mass += body.mass;
  for (const sim::Body& body : rigid.model.bodies) rigid_mass += body.mass;
  EXPECT_NEAR(mass, rigid_mass, 1e-12 * rigid_mass);
  // Its loops close at the rigid array's automatic bandwidth, not at 25
  // times its pins' tilt rate.
  ASSERT_TRUE(scene.regulator.v_max);
  EXPECT_EQ(*scene.regulator.v_max, sim::Dynamics(rigid).regulator()->v_max());
  const sim::Scene automatic =
      sim::apply_overrides(studies::generate_flexible_pantograph(6), {{"regulator.v_max", "auto"}}).scene;
  EXPECT_LT(100 * *scene.regulator.v_max, sim::Dynamics(automatic).regulator()->v_max());
}

TEST(Generator, LargerArraysRegularizeFinerAndWatchBdfsStabilityLimit) {
  using Detection = sim::StabilityLimitDetection;
  // The reference size keeps the reference's settings (SCENES.md).
  const sim::SceneFile reference = studies::generate_pantograph(3);
  EXPECT_FALSE(reference.scene.regulator.regularization);
  EXPECT_EQ(reference.scene.run.stability_limit_detection, Detection::off);
  EXPECT_EQ(sim::write_scene_text(reference).find("stability_limit_detection"), std::string::npos);

  // Rigid arrays take the automatic regularization (test_automatic_regularization.cpp);
  // flexible ones the finest.
  const sim::SceneFile rigid = studies::generate_pantograph(10);
  EXPECT_FALSE(rigid.scene.regulator.regularization);
  EXPECT_EQ(studies::generate_flexible_pantograph(6).scene.regulator.regularization,
            sim::Regulator::kFinestRegularization);
  EXPECT_EQ(studies::generate_flexible_pantograph(6).scene.run.stability_limit_detection, Detection::on);
  EXPECT_EQ(studies::generate_pantograph(10, studies::CrossPivots::compliant).scene.run.stability_limit_detection,
            Detection::on);
  // The 3-stage flexible array is pantograph_flexible, which watches from its latch-up on.
  EXPECT_EQ(studies::generate_flexible_pantograph(3, studies::Snubbers::none).scene.run.stability_limit_detection,
            Detection::after_latch);
  EXPECT_EQ(test::scene_file("pantograph_flexible").run.stability_limit_detection, Detection::after_latch);
  // The setting survives the file.
  for (const sim::SceneFile& file : {rigid, studies::generate_flexible_pantograph(3)}) {
    const std::string text = sim::write_scene_text(file);
    EXPECT_EQ(sim::read_scene_text(text, "written").scene.run.stability_limit_detection,
              file.scene.run.stability_limit_detection);
  }
  EXPECT_NE(sim::write_scene_text(rigid).find("stability_limit_detection: true"), std::string::npos);
  try {
    test::scene_file("pantograph", {{"run.stability_limit_detection", "maybe"}});
    ADD_FAILURE() << "a setting that is no boolean nor after_latch was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("run.stability_limit_detection"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("after_latch"), std::string::npos) << e.what();
  }
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

TEST(LargeArray, ArraysReleasedNextToTheirBranchPointStartWithTheirLoopsClosed) {
  // Their weakest loop modes lie below the rank tolerance at the stowed
  // start (16 stages: the dense analysis; 30: the sparse one), where the
  // regulator closes them with the gain a = w / (w + delta) << 1 and rings
  // at sqrt(a) v_max. Its integral starts where it settles, so the loop
  // forces are the rigid ones from t = 0: started from zero, the loops
  // opened by 2.4e-9 m and 1.4e-11 m over the first 0.01 s, and the
  // 30-stage array took 408 steps for its first 0.2 s at rtol 1e-7 (20 now).
  for (const int stages : {16, 30}) {
    const sim::Scene scene =
        sim::apply_overrides(studies::generate_pantograph(stages), {{"run.t_end", "0.01"}, {"run.sample", "1e-4"}})
            .scene;
    const sim::RunResult run = sim::simulate(scene, scene.run);
    ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
    const sim::RunSummary s = sim::summarize(scene, run);
    EXPECT_LT(s.max_closure_gap, 1e-12) << stages << " stages";
    EXPECT_LT(s.max_closure_angle, 1e-12) << stages << " stages";
  }
}

TEST(LargeArray, ThirtyStageLoopsDoNotHangOnTheRegularization) {
  // Released 0.01 rad off the stowed stack, the 30-stage array's weakest
  // loop modes lie at 1.2e-10 of W's largest eigenvalue. At the automatic
  // regularization (the finest, 2e-9) its angles hardly move when it is a
  // hundredth of that (2.6e-8 rad over 0.5 s); at the reference scenes'
  // 2e-6, which softens those modes, the loops lag by 9.7e-6 rad (1.2e-4
  // rad while the regulator's integral started from zero instead of where
  // it settles, Dynamics::initial_state: most of that lag was its start).
  const auto run_at = [](const std::string& regularization) {
    const sim::Scene scene =
        sim::apply_overrides(studies::generate_pantograph(30), {{"run.t_end", "0.5"},
                                                                {"run.rtol", "1e-8"},
                                                                {"run.atol", "1e-10"},
                                                                {"regulator.regularization", regularization}})
            .scene;
    sim::RunResult run = sim::simulate(scene, scene.run);
    EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
    return run;
  };
  const sim::Scene scene = studies::generate_pantograph(30).scene;
  ASSERT_FALSE(scene.regulator.regularization);
  EXPECT_EQ(sim::Dynamics(scene).regulator()->regularization(), sim::Regulator::kFinestRegularization);
  const sim::RunResult automatic = run_at("auto"), finer = run_at("2e-11"), coarse = run_at("2e-6");
  EXPECT_LT(test::largest_angle_difference(scene.model, automatic, finer), 1e-6);
  EXPECT_GT(test::largest_angle_difference(scene.model, coarse, finer), 5e-6);
}

TEST(LargeArray, KrylovStepsFollowTheMotionNotTheLinearSolves) {
  // Over its first 2 s the 30-stage array barely moves and BDF's steps grow
  // to h v_max of several hundred. With GMRES held to SUNDIALS' fixed 0.05
  // of Newton's tolerance the corrections' error set the step (1,391 steps
  // at rtol 1e-8); with the factor scaled by 1 / (h v_max) the motion does
  // (90), to the same angles.
  const auto run_at = [](const std::string& rtol, const std::string& atol) {
    const sim::Scene scene = sim::apply_overrides(studies::generate_pantograph(30),
                                                  {{"run.t_end", "2"}, {"run.rtol", rtol}, {"run.atol", atol}})
                                 .scene;
    sim::RunResult run = sim::simulate(scene, scene.run);
    EXPECT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
    return run;
  };
  const sim::RunResult run = run_at("1e-8", "1e-10"), tight = run_at("1e-10", "1e-12");
  EXPECT_LT(run.stats.steps, 300);
  EXPECT_LT(test::largest_angle_difference(studies::generate_pantograph(30).scene.model, run, tight), 1e-6);
}

TEST(LargeArray, KrylovNewtonConvergesThroughCompliantPinsAndPlates) {
  // The flexible pantograph's loops close through its pins' compliant hinges
  // and its plates' nodes, which the Newton preconditioner leaves to GMRES.
  // With SUNDIALS' default Krylov space of 5, Newton failed 10 times over
  // this span (1297 steps); with 2m + 5 (41) it converges every time.
  const sim::Scene scene = test::scene_file("pantograph_flexible", {{"run.t_end", "0.1"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished) << sim::describe(run.failure);
  EXPECT_GT(run.stats.linear_iterations, 0);
  EXPECT_EQ(run.stats.nonlinear_failures, 0);
}

TEST(ClosureSolver, SparseOnTenLoops) {
  const sim::Scene scene = studies::generate_pantograph(10).scene;
  VectorXd q(scene.model.nq);
  for (int k = 0; k < q.size(); ++k) q[k] = 0.5 * scene.q0[k];
  expect_closure_solve_matches_dense(scene, sim::ClosureSolverKind::sparse, q, 1e-5);
}

}  // namespace
}  // namespace unfurl
