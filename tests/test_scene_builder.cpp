// Scenes built in code: the same rules as a file's, errors by field path,
// the same run as the file's scene; and the writer, whose text reads back
// to the same scene.
#include <gtest/gtest.h>

#include "support.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/scene_validation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

void expect_same_run(const sim::Scene& a, const sim::Scene& b) {
  sim::RunSettings settings = a.run;
  settings.t_end = 8;  // through the latch-up at 7.39 s
  const sim::RunResult ra = sim::simulate(a, settings), rb = sim::simulate(b, settings);
  ASSERT_EQ(ra.status, sim::RunStatus::finished) << sim::describe(ra.failure);
  ASSERT_EQ(ra.trajectory.samples.size(), rb.trajectory.samples.size());
  for (std::size_t k = 0; k < ra.trajectory.samples.size(); ++k) {
    ASSERT_EQ(ra.trajectory.samples[k].y, rb.trajectory.samples[k].y) << "t = " << ra.trajectory.samples[k].t;
    ASSERT_EQ(ra.trajectory.samples[k].loads.element, rb.trajectory.samples[k].loads.element);
  }
  ASSERT_EQ(ra.trajectory.events.size(), rb.trajectory.events.size());
  EXPECT_EQ(ra.stats.steps, rb.stats.steps);
}

TEST(SceneBuilder, PantographBuiltInCodeRunsAsTheFilesPantograph) {
  // generate_pantograph builds with SceneBuilder, no YAML on the way.
  const sim::SceneFile built = studies::generate_pantograph(3);
  EXPECT_EQ(built.scene.source, "generated");
  expect_same_run(built.scene, test::scene_file("pantograph"));
}

TEST(SceneBuilder, PendulumInCode) {
  sim::SceneBuilder b("pendulum");
  b.fixed_base("ground").gravity(sim::Vec3(0, 0, -9.81));
  sim::Body rod;
  rod.name = "rod";
  rod.mass = 2;
  rod.com = sim::Vec3(0, 0, -0.5);
  rod.inertia_com = sim::Vec3(0.1, 0.1, 0.02).asDiagonal();
  b.body(rod, "ground", sim::joints::revolute("hinge", sim::Vec3(2, 0, 0), sim::Vec3::Zero(), sim::Vec3::Zero()));
  b.initial_position("hinge", {0.3});
  const sim::SceneFile file = b.build();
  EXPECT_EQ(file.scene.model.joints[0].axis, sim::Vec3::UnitX()) << "axes are made unit";
  EXPECT_EQ(file.scene.q0, std::vector<double>{0.3});
  EXPECT_EQ(file.scene.gravity(), sim::Vec3(0, 0, -9.81));
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished);
}

// What build() says of a scene that breaks a rule: the field and why.
std::pair<std::string, std::string> build_error(sim::SceneBuilder& b) {
  try {
    b.build();
  } catch (const sim::SceneInvalid& e) {
    return {e.field(), e.reason()};
  }
  return {"", "no error"};
}

sim::Body unit_body(const std::string& name) {
  sim::Body body;
  body.name = name;
  body.mass = 1;
  body.inertia_com = sim::Mat3::Identity();
  return body;
}

TEST(SceneBuilder, ErrorsNameTheFieldPath) {
  {
    sim::SceneBuilder b("bad");
    sim::Body body = unit_body("a");
    body.inertia_com = sim::Vec3(1, 1, 3).asDiagonal();
    b.body(body, "base", sim::joints::revolute("j", sim::Vec3::UnitX(), sim::Vec3::Zero(), sim::Vec3::Zero()));
    const auto [field, reason] = build_error(b);
    EXPECT_EQ(field, "bodies[0] (a).inertia");
    EXPECT_NE(reason.find("no body has these principal moments"), std::string::npos) << reason;
  }
  {
    sim::SceneBuilder b("bad");
    b.body(unit_body("a"), "base",
           sim::joints::revolute("j", sim::Vec3::UnitX(), sim::Vec3::Zero(), sim::Vec3::Zero()));
    auto spring = std::make_shared<sim::JointSpring>(b.joint_index("j", "springs[0].joint"));
    spring->stiffness = -1;
    b.element(spring);
    const auto [field, reason] = build_error(b);
    EXPECT_EQ(field, "springs[0].stiffness");
    EXPECT_EQ(reason, "must not be negative, got -1");
  }
  {
    sim::SceneBuilder b("bad");
    b.body(unit_body("a"), "base",
           sim::joints::revolute("j", sim::Vec3::UnitX(), sim::Vec3::Zero(), sim::Vec3::Zero()));
    EXPECT_THROW(b.joint_index("k", "latches[0].joint"), sim::SceneInvalid);
    EXPECT_THROW(b.body(unit_body("b"), "nowhere", sim::Joint{}), sim::SceneInvalid);
  }
}

TEST(SceneWriter, EveryBuiltInSceneReadsBackToTheSameRun) {
  for (const std::string& name : sim::builtin_scene_names()) {
    const sim::SceneFile file = sim::read_builtin_scene(name);
    const std::string text = sim::write_scene_text(file);
    const sim::SceneFile back = sim::read_scene_text(text, "written:" + name);
    EXPECT_EQ(sim::write_scene_text(back), text) << name;
    sim::Scene short_run = file.scene, short_back = back.scene;
    for (sim::Scene* s : {&short_run, &short_back}) s->run.t_end = std::min(s->run.t_end, 0.2);
    const sim::RunResult a = sim::simulate(short_run, short_run.run), b = sim::simulate(short_back, short_back.run);
    ASSERT_EQ(a.trajectory.samples.size(), b.trajectory.samples.size()) << name;
    EXPECT_EQ(a.trajectory.samples.back().y, b.trajectory.samples.back().y) << name;
  }
}

// A scene built in code may come without its drawing (no visuals at all):
// it writes without meshes and reads back to the same mechanism.
TEST(SceneWriter, ASceneWithoutVisualsWritesWithoutMeshes) {
  for (const char* name : {"pantograph", "pantograph_free"}) {
    const sim::SceneFile drawn = sim::read_builtin_scene(name);
    const sim::SceneFile bare{drawn.scene, {}};
    const std::string text = sim::write_scene_text(bare);
    EXPECT_EQ(text.find("mesh:"), std::string::npos) << name;
    const sim::SceneFile back = sim::read_scene_text(text, std::string("bare:") + name);
    EXPECT_EQ(back.scene.model.size(), drawn.scene.model.size()) << name;
    EXPECT_EQ(back.scene.q0, drawn.scene.q0) << name;
  }
}

TEST(SceneWriter, OverridesGoThroughTheText) {
  const sim::SceneFile file = studies::generate_zfold(2);
  const sim::SceneFile changed = sim::apply_overrides(file, {{"springs.j1.stiffness", "0.2"}});
  EXPECT_EQ(changed.scene.elements_of<sim::JointSpring>()[0]->stiffness, 0.2);
  EXPECT_EQ(file.scene.elements_of<sim::JointSpring>()[0]->stiffness, 0.1);
}

}  // namespace
}  // namespace unfurl
