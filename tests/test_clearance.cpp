// Clearance against closed forms: an arm turning at a constant rate past a
// body it is not jointed to, its closest approach and when, from spheres,
// boxes and a mesh of the same box; a sweep through the other body gives a
// contact span whose ends are known; jointed pairs and `collision: none`
// are left out, and a loop's image counts as its split body.
#include <gtest/gtest.h>

#include <cmath>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/body_solids.hpp"
#include "unfurl/studies/clearance.hpp"
#include "unfurl/studies/clearance_broad_phase.hpp"

namespace unfurl {
namespace {

// Two bodies hinged about x at the base's origin, no gravity: the arm turns
// at 1 rad/s (its angle is t), the post stays at rest. The arm's solid sits
// at its tip (0, 1, 0), which passes (0, 0, 1) at t = pi/2.
std::string arm_and_post(const std::string& arm_solid, const std::string& post_solid) {
  return R"(
name: arm
base: {name: ground, collision: none}
bodies:
  - name: arm
    parent: ground
    mass: 1.0
    com: [0, 0.5, 0]
    inertia: [0.1, 0.1, 0.1]
    collision: )" + arm_solid + R"(
    joint: {name: a, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
  - name: post
    parent: ground
    mass: 1.0
    inertia: [0.1, 0.1, 0.1]
    collision: )" + post_solid + R"(
    joint: {name: p, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}
initial:
  dq: {a: 1.0}
run: {t_end: 3, rtol: 1.0e-10, atol: 1.0e-12, sample: 0.05}
)";
}

// arm_and_post with a third body, a sphere of 0.2 hinged at (x, 0, 0).
std::string with_far_body(std::string text, double x) {
  const std::string far = R"(
  - name: far
    parent: ground
    mass: 1.0
    inertia: [0.1, 0.1, 0.1]
    collision: [{sphere: 0.2}]
    joint: {name: f, type: revolute, axis: [1, 0, 0], parent_point: [)" + std::to_string(x) + R"(, 0, 0], child_point: [0, 0, 0]}
initial:)";
  text.replace(text.find("\ninitial:"), 9, far);
  return text;
}

// A unit cube's twelve triangles, centred on the origin.
studies::Triangles unit_cube() {
  studies::Triangles cube;
  for (int i = 0; i < 8; ++i) cube.vertices.push_back(sim::Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) - sim::Vec3::Constant(0.5));
  cube.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return cube;
}

sim::Clearance clearance_of(const std::string& text) {
  const sim::SceneFile file = sim::read_scene_text(text, "arm");
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, sim::RunStatus::finished);
  const studies::MeshReader read = [](const std::string& name) {
    if (name != "cube") throw std::runtime_error("no mesh " + name);
    return unit_cube();
  };
  return studies::check_clearance(file.scene, studies::body_solids(file.scene, file.visuals, read), run.trajectory);
}

TEST(Clearance, SpheresPassAtTheirClosedFormDistanceAndTime) {
  // Centres sqrt(2 - 3 sin t + 2.25) apart: 0.5 at t = pi/2, less the radii 0.1 and 0.2.
  const sim::Clearance c = clearance_of(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]",
                                                     "[{sphere: 0.2, offset: [0, 0, 1.5]}]"));
  ASSERT_EQ(c.pairs.size(), 1u);  // the ground is left out, and jointed to both
  EXPECT_EQ(c.pairs[0].body_a, "arm");
  EXPECT_EQ(c.pairs[0].body_b, "post");
  EXPECT_NEAR(c.pairs[0].distance, 0.2, 1e-8);
  // The minimum is flat: a distance right to 1e-8 places it to about 1e-4.
  EXPECT_NEAR(c.pairs[0].t, M_PI / 2, 1e-3);
  EXPECT_TRUE(c.clear());
  EXPECT_EQ(c.samples, 61);
  EXPECT_LT(c.distance_queries, 61 + 40);
}

// A cancel set before the check stops it before any pair is measured (the
// workbench's superseded run).
TEST(Clearance, ACancelStopsItBeforeAnyPairIsMeasured) {
  const sim::SceneFile file =
      sim::read_scene_text(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]", "[{sphere: 0.2, offset: [0, 0, 1.5]}]"), "arm");
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  const studies::BodySolids solids = studies::body_solids(file.scene, file.visuals, nullptr);
  std::atomic<bool> cancel{true};
  EXPECT_EQ(studies::check_clearance(file.scene, solids, run.trajectory, &cancel).distance_queries, 0);
  cancel = false;
  EXPECT_EQ(studies::check_clearance(file.scene, solids, run.trajectory, &cancel).pairs.size(), 1u);
}

TEST(Clearance, PairsThatNeverComeNearAreCertifiedWithoutMeasuring) {
  // The far body is 50 m off: its pairs are left out, the arm and post's
  // closest approach stays the closed form's.
  const sim::Clearance c = clearance_of(
      with_far_body(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]", "[{sphere: 0.2, offset: [0, 0, 1.5]}]"), 50));
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs_beyond, 2);
  EXPECT_EQ(c.pairs[0].body_b, "post");
  EXPECT_NEAR(c.pairs[0].distance, 0.2, 1e-8);
  EXPECT_NEAR(c.listed_within, 0.34, 1e-12);  // a tenth of the post's reach, doubled once
  EXPECT_LT(c.distance_queries, 61 + 40);
}

TEST(Clearance, ThePairsAreMeasuredFartherOutUntilTheClosestIsFound) {
  // The arm's sphere (reach 1.1) and the far body's, 50 m off: the margin
  // doubles from 0.11 until it takes the pair in (at 56.3 m), and its
  // distance is exact; every pair measured, no margin bounds the others.
  const sim::Clearance c = clearance_of(with_far_body(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]", "none"), 50));
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs_beyond, 0);
  EXPECT_NEAR(c.pairs[0].distance, std::sqrt(2501.0) - 0.3, 1e-8);
  EXPECT_TRUE(std::isinf(c.listed_within));
}

// Whether two boxes, body a's and body b's, come within `margin` over
// their poses at the samples (one per sample).
bool near(const studies::BodyBox& a, const studies::BodyBox& b, const std::vector<sim::Pose>& pa,
          const std::vector<sim::Pose>& pb, double margin) {
  const studies::NearPairs pairs({a, b}, pa.size(),
                                 [&](std::size_t k, int i) -> const sim::Pose& { return i == 0 ? pa[k] : pb[k]; },
                                 margin);
  EXPECT_EQ(pairs.near(0, 1), pairs.near(1, 0));
  return pairs.near(0, 1);
}

sim::Pose at(const sim::Vec3& position, double turn_about_z = 0) {
  sim::Pose p;
  p.position = position;
  p.rotation = Eigen::AngleAxisd(turn_about_z, sim::Vec3::UnitZ()).toRotationMatrix().transpose();
  return p;
}

TEST(ClearanceBroadPhase, BoxesNearAtASampleOrCrossingBetweenTwo) {
  const studies::BodyBox unit{sim::Vec3::Zero(), sim::Vec3::Constant(0.5), std::sqrt(0.75)};
  // 1.5 apart along y.
  EXPECT_FALSE(near(unit, unit, {at({0, 0, 0})}, {at({0, 2.5, 0})}, 1.4));
  EXPECT_TRUE(near(unit, unit, {at({0, 0, 0})}, {at({0, 2.5, 0})}, 1.6));
  // Far apart at both samples, through each other between them.
  EXPECT_TRUE(near(unit, unit, {at({-10, 0, 0}), at({10, 0, 0})}, {at({10, 0, 0}), at({-10, 0, 0})}, 0));
  // A 4 x 1 x 1 box turned a quarter about z reaches 2 along y: 0.5 from
  // the unit box at y = 3 (2 when not turned).
  const studies::BodyBox bar{sim::Vec3::Zero(), sim::Vec3(2, 0.5, 0.5), std::sqrt(4.5)};
  EXPECT_FALSE(near(bar, unit, {at({0, 0, 0}, M_PI / 2)}, {at({0, 3, 0})}, 0.4));
  EXPECT_TRUE(near(bar, unit, {at({0, 0, 0}, M_PI / 2)}, {at({0, 3, 0})}, 0.6));
  EXPECT_FALSE(near(bar, unit, {at({0, 0, 0})}, {at({0, 3, 0})}, 1.9));
  // Turning from 0 to a quarter between two samples sweeps it through.
  EXPECT_TRUE(near(bar, unit, {at({0, 0, 0}), at({0, 0, 0}, M_PI / 2)}, {at({0, 3, 0}), at({0, 3, 0})}, 0.6));
  // A body without solids is never near.
  EXPECT_FALSE(near(studies::BodyBox{}, unit, {at({0, 0, 0})}, {at({0, 0, 0})}, 100));
}

TEST(ClearanceBroadPhase, TheEnclosingBoxOfABoxAndOfTheSameBoxAsAMesh) {
  studies::Solid box;
  box.kind = sim::CollisionShape::Kind::box;
  box.size = sim::Vec3(0.2, 0.4, 0.6);
  box.offset = sim::Vec3(1, 2, 3);
  studies::Solid mesh;
  mesh.mesh = unit_cube();
  for (sim::Vec3& v : mesh.mesh.vertices) v = v.cwiseProduct(box.size);
  mesh.offset = box.offset;
  for (const studies::Solid& s : {box, mesh}) {
    const studies::BodyBox e = studies::enclosing_box({s});
    EXPECT_NEAR((e.centre - box.offset).norm(), 0, 1e-15);
    EXPECT_NEAR((e.half - 0.5 * box.size).norm(), 0, 1e-15);
    EXPECT_NEAR(e.radius, 0.5 * box.size.norm(), 1e-15);
  }
  EXPECT_LT(studies::enclosing_box({}).radius, 0);
}

TEST(Clearance, ABoxAndTheSameBoxAsAMeshGiveTheSameDistance) {
  // The sphere's top at 1.1 when the arm is upright, the box's underside at 1.4.
  const std::string sphere = "[{sphere: 0.1, offset: [0, 1, 0]}]";
  const sim::Clearance box = clearance_of(arm_and_post(sphere, "[{box: [0.2, 0.2, 0.2], offset: [0, 0, 1.5]}]"));
  const sim::Clearance mesh =
      clearance_of(arm_and_post(sphere, "[{mesh: cube, scale: [0.2, 0.2, 0.2], offset: [0, 0, 1.5]}]"));
  ASSERT_EQ(box.pairs.size(), 1u);
  ASSERT_EQ(mesh.pairs.size(), 1u);
  EXPECT_NEAR(box.pairs[0].distance, 0.3, 1e-8);
  EXPECT_NEAR(mesh.pairs[0].distance, 0.3, 1e-8);
  EXPECT_NEAR(mesh.pairs[0].t, M_PI / 2, 1e-3);
}

TEST(Clearance, ASweepThroughAnotherBodyIsAContactSpanWithItsClosedFormEnds) {
  // Spheres of 0.1 and 0.05 touch where the centres' chord 2 sin(|t - pi/2| / 2)
  // is 0.15: for |t - pi/2| <= 2 asin(0.075).
  const sim::Clearance c = clearance_of(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]",
                                                     "[{sphere: 0.05, offset: [0, 0, 1]}]"));
  ASSERT_EQ(c.contacts.size(), 1u);
  const double half = 2 * std::asin(0.075);
  // Seen at the samples (0.05 s apart) inside the span, or between them.
  EXPECT_GE(c.contacts[0].t_begin, M_PI / 2 - half);
  EXPECT_LT(c.contacts[0].t_begin, M_PI / 2 - half + 0.05);
  EXPECT_LE(c.contacts[0].t_end, M_PI / 2 + half);
  EXPECT_GT(c.contacts[0].t_end, M_PI / 2 + half - 0.05);
  EXPECT_FALSE(c.contacts[0].at_start);
  EXPECT_FALSE(c.clear());
  EXPECT_EQ(c.pairs[0].distance, 0.0);
}

TEST(Clearance, AGrazeBetweenSamplesIsFound) {
  // Centres 0.149 apart at t = pi/2, the radii 0.15: they overlap while
  // sin t >= 0.99987, within 0.0161 of pi/2, between the samples at 1.55
  // and 1.60.
  const sim::Clearance c = clearance_of(arm_and_post("[{sphere: 0.1, offset: [0, 1, 0]}]",
                                                     "[{sphere: 0.05, offset: [0, 0, 1.149]}]"));
  ASSERT_EQ(c.contacts.size(), 1u);
  EXPECT_NEAR(c.contacts[0].t_begin, M_PI / 2, 0.0161);
  EXPECT_EQ(c.contacts[0].t_begin, c.contacts[0].t_end);
}

TEST(Clearance, ABodyWithoutASolidIsNamedAndLeftOut) {
  const sim::SceneFile file = sim::read_scene_text(arm_and_post("none", "[{sphere: 0.2}]"), "arm");
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  const sim::Clearance c =
      studies::check_clearance(file.scene, studies::body_solids(file.scene, file.visuals, nullptr), run.trajectory);
  EXPECT_TRUE(c.pairs.empty());
  EXPECT_EQ(c.without_solid, (std::vector<std::string>{"ground", "arm"}));
}

TEST(Clearance, AMeshThatCannotBeReadIsNamed) {
  const sim::SceneFile file =
      sim::read_scene_text(arm_and_post("[{mesh: nowhere}]", "[{sphere: 0.2}]"), "arm");
  std::vector<std::string> unread;
  const studies::BodySolids solids = studies::body_solids(
      file.scene, file.visuals, [](const std::string& name) -> studies::Triangles { throw std::runtime_error("no " + name); },
      &unread);
  ASSERT_EQ(unread.size(), 1u);
  EXPECT_NE(unread[0].find("nowhere"), std::string::npos) << unread[0];
  EXPECT_TRUE(solids.bodies[0].empty());
}

TEST(Clearance, ShapesAreWrittenBackAsRead) {
  const std::string text = arm_and_post(
      "[{sphere: 0.1, offset: [0, 1, 0]}, {cylinder: [0.02, 1], rotation: [1, 0, 0, 90], offset: [0, 0.5, 0]}]",
      "[{mesh: cube, scale: [0.2, 0.3, 0.4], offset: [0, 0, 1.5]}, {box: [0.1, 0.2, 0.3]}]");
  const sim::SceneFile file = sim::read_scene_text(text, "arm");
  const sim::SceneFile again = sim::read_scene_text(sim::write_scene_text(file), "again");
  ASSERT_TRUE(again.visuals.base.collision.has_value());
  EXPECT_TRUE(again.visuals.base.collision->empty());
  ASSERT_EQ(again.visuals.bodies.size(), 2u);
  for (int b = 0; b < 2; ++b) {
    const auto& before = *file.visuals.bodies[b].collision;
    const auto& after = *again.visuals.bodies[b].collision;
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t s = 0; s < before.size(); ++s) {
      EXPECT_EQ(after[s].kind, before[s].kind);
      EXPECT_EQ(after[s].size, before[s].size);
      EXPECT_EQ(after[s].radius, before[s].radius);
      EXPECT_EQ(after[s].length, before[s].length);
      EXPECT_EQ(after[s].mesh, before[s].mesh);
      EXPECT_EQ(after[s].scale, before[s].scale);
      EXPECT_EQ(after[s].rotation_axis, before[s].rotation_axis);
      EXPECT_EQ(after[s].rotation_deg, before[s].rotation_deg);
      EXPECT_EQ(after[s].offset, before[s].offset);
    }
  }
}

TEST(Clearance, ALoopsImageIsItsSplitBodysOtherHalf) {
  // The pantograph's three loops close through images of chain A's panels:
  // no pair names an image, and the panels a loop joins are not a pair.
  const sim::SceneFile file = sim::read_builtin_scene("pantograph", {{"run.t_end", "2"}});
  const sim::RunResult run = sim::simulate(file.scene, file.scene.run);
  const studies::MeshReader box = [](const std::string&) {
    studies::Triangles cube = unit_cube();
    for (sim::Vec3& v : cube.vertices) v *= 0.01;  // small solids: nothing touches
    return cube;
  };
  const sim::Clearance c =
      studies::check_clearance(file.scene, studies::body_solids(file.scene, file.visuals, box), run.trajectory);
  // 9 bodies (the bus, 11 less the 3 images): 36 pairs less the 8 joints
  // between them and the 3 loop pivots.
  EXPECT_EQ(c.pairs.size() + c.pairs_beyond, 36u - 8u - 3u);
  for (const sim::PairClearance& p : c.pairs) {
    EXPECT_EQ(p.body_a.find("image"), std::string::npos);
    EXPECT_EQ(p.body_b.find("image"), std::string::npos);
  }
  EXPECT_TRUE(c.clear());
}

}  // namespace
}  // namespace unfurl
