// Loads drawn as arrows: a pendulum's hinge force against its closed form,
// latch torques along their hinge axes, the arrows in the picture where
// the hinge is, and `unfurl render --loads`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "png_read.hpp"
#include "support.hpp"
#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/mesh_file.hpp"
#include "unfurl/render/gl_context.hpp"
#include "unfurl/render/load_arrows.hpp"
#include "unfurl/sim/elements/latch.hpp"
#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl {
namespace {

std::vector<sim::Pose> poses_at(const sim::Scene& scene, const sim::Trajectory& tr, double t) {
  std::vector<double> q;
  tr.coordinates_at(t, q);
  std::vector<sim::Pose> poses;
  sim::body_poses(scene.model, q.data(), poses);
  return poses;
}

// The pendulum released from rest at q0 passes its lowest point with
// I w^2 / 2 = m g d (1 - cos q0), its hinge then holding it up against its
// weight and the centripetal force: F = m g + m d w^2, the largest of the
// swing. The arrow there points straight up from the hinge, full length.
TEST(LoadArrows, PendulumsHingeForceAtTheBottomIsItsClosedForm) {
  sim::Scene scene = test::scene_file("pendulum", {{"run.t_end", "1.2"}, {"run.sample", "0.0005"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const double m = 1, g = 9.81, d = 1, I = 0.004 + m * d * d, q0 = 2.5;
  const double w2 = 2 * m * g * d * (1 - std::cos(q0)) / I, F = m * g + m * d * w2;
  const float size = 2;
  const render::LoadArrowScale scale = render::load_arrow_scale(scene, run.trajectory, size);
  EXPECT_NEAR(scale.peak_force, F, 2e-3 * F);
  EXPECT_EQ(scale.peak_torque, 0);  // no latch
  EXPECT_FLOAT_EQ(scale.reach, 0.25f * size);
  // The sample nearest the bottom (q = 0).
  const sim::Sample* bottom = &run.trajectory.samples.front();
  for (const sim::Sample& s : run.trajectory.samples)
    if (std::abs(s.y[0]) < std::abs(bottom->y[0])) bottom = &s;
  ASSERT_LT(std::abs(bottom->y[0]), 0.01);
  const std::vector<render::LoadArrow> arrows =
      render::load_arrows(scene, run.trajectory, *bottom, poses_at(scene, run.trajectory, bottom->t), scale);
  ASSERT_EQ(arrows.size(), 1u);
  EXPECT_EQ(arrows[0].kind, render::LoadArrow::Kind::force);
  EXPECT_LT(arrows[0].from.norm(), 1e-6f);  // at the hinge
  EXPECT_NEAR(arrows[0].vector.z(), scale.reach, 2e-3 * scale.reach);
  EXPECT_NEAR(arrows[0].vector.y(), 0, 0.02 * scale.reach);
  // Lengths in proportion to the force: at release, at rest, the hinge
  // takes the weight's radial part m g cos(q0) and, of its tangential
  // part, the share the bob's own inertia about its centre does not.
  const std::vector<render::LoadArrow> start = render::load_arrows(
      scene, run.trajectory, run.trajectory.samples.front(), poses_at(scene, run.trajectory, 0), scale);
  ASSERT_EQ(start.size(), 1u);
  const double F0 = std::hypot(m * g * std::cos(q0), m * g * std::sin(q0) * (1 - m * d * d / I));
  EXPECT_NEAR(start[0].vector.norm() / scale.reach, F0 / F, 1e-4);
}

// Each engaged latch's torque is an arrow along its hinge axis, as long as
// its share of the run's largest, pointing by the right-hand rule.
TEST(LoadArrows, LatchTorquesLieAlongTheirHingeAxes) {
  sim::Scene scene = test::scene_file("zfold");
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const render::LoadArrowScale scale = render::load_arrow_scale(scene, run.trajectory, 4);
  ASSERT_GT(scale.peak_torque, 0);
  const sim::Sample& last = run.trajectory.samples.back();
  const std::vector<sim::Pose> poses = poses_at(scene, run.trajectory, last.t);
  int torques = 0;
  for (const render::LoadArrow& a : render::load_arrows(scene, run.trajectory, last, poses, scale)) {
    if (a.kind != render::LoadArrow::Kind::torque) continue;
    ++torques;
    bool matched = false;
    for (const sim::Latch* latch : scene.latches()) {
      const sim::Joint& joint = scene.model.joints[latch->joint];
      const sim::Pose& child = poses[latch->joint];
      if ((child.to_base(joint.child_point).cast<float>() - a.from).norm() > 1e-5f) continue;
      const double tau = test::load_of(run.trajectory.load_columns, last.loads, "latch_torque." + joint.name);
      const Eigen::Vector3f axis = (child.rotation.transpose() * joint.axis).cast<float>();
      EXPECT_NEAR(a.vector.dot(axis), tau / scale.peak_torque * scale.reach, 1e-4 * scale.reach) << joint.name;
      EXPECT_NEAR(a.vector.cross(axis).norm(), 0, 1e-5f * scale.reach) << joint.name;
      matched = true;
    }
    EXPECT_TRUE(matched) << "a torque arrow at no latched hinge";
  }
  EXPECT_GT(torques, 0);
}

// In a picture, the pendulum's hinge force at the bottom of its swing is
// drawn above the hinge; without arrows nothing there changes.
TEST(LoadArrows, DrawnAboveTheHingeInThePicture) {
  const sim::SceneFile file = sim::read_scene_file(test::asset("scenes/pendulum.yaml"));
  sim::Scene scene = file.scene;
  scene.run.t_end = 1.2;
  const sim::RunResult run = sim::simulate(scene, scene.run);
  auto context = render::make_offscreen_context();
  const int w = 320, h = 240;
  render::FrameRenderer renderer(scene, file.visuals, w, h, {render::builtin_mesh_directory()});
  // Where the bob hangs at rest, seen from the side (along the hinge axis).
  std::vector<sim::Pose> poses;
  std::vector<double> q(1, 0.0);
  sim::body_poses(scene.model, q.data(), poses);
  render::Camera camera;
  camera.target = Eigen::Vector3f(0, 0, 0.1f);
  camera.azimuth_deg = 0;
  camera.elevation_deg = 0;
  camera.distance = 1.5f;
  const render::LoadArrowScale scale = render::load_arrow_scale(scene, run.trajectory, 2);
  const sim::Sample& s = run.trajectory.sample_at(run.trajectory.t_end());
  std::vector<render::LoadArrow> arrows = render::load_arrows(scene, run.trajectory, s, poses, scale);
  ASSERT_EQ(arrows.size(), 1u);
  arrows[0].vector = Eigen::Vector3f(0, 0, scale.reach);  // as at the bottom
  render::Image plain, loaded;
  renderer.frame(poses, "plain", camera, plain, {}, "");
  renderer.frame(poses, "plain", camera, loaded, arrows, "");
  // The hinge at (0, 0, 0) and 0.5 m above it, in pixels.
  const Eigen::Matrix4f P = camera.projection(float(w) / h) * camera.view();
  const auto row = [&](float z) {
    const Eigen::Vector4f c = P * Eigen::Vector4f(0, 0, z, 1);
    return static_cast<int>((1 - c.y() / c.w()) / 2 * h);
  };
  int above = 0, below = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t *a = plain.pixel(x, y), *b = loaded.pixel(x, y);
      if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 60) continue;
      (y <= row(0) + 2 && y >= row(scale.reach) - 2 ? above : below)++;
    }
  EXPECT_GT(above, 300);
  EXPECT_LT(below, above / 20) << "the arrow is drawn where the hinge force acts, up from the hinge";
}

// `unfurl render --loads` writes frames with the arrows and their legend;
// --load-scale alone and --loads with a mode are refused.
TEST(RenderCommand, LoadsAreDrawnAsArrowsOnRequest) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("unfurl_arrows_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string common = std::string(UNFURL_BINARY) + " render zfold --to 2 --fps 1 --size 320x180 --quiet";
  ASSERT_EQ(test::run_command(common + " --out " + (dir / "plain").string()).code, 0);
  ASSERT_EQ(test::run_command(common + " --loads --load-scale 2 --out " + (dir / "loads").string()).code, 0);
  const render::Image a = test::read_png((dir / "plain" / "frame_00002.png").string()),
                      b = test::read_png((dir / "loads" / "frame_00002.png").string());
  int differ = 0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) differ += std::abs(int(a.rgb[k]) - int(b.rgb[k])) > 40;
  EXPECT_GT(differ, 300);
  const test::CommandOutcome alone = test::run_command(common + " --load-scale 2 --out " + (dir / "x").string());
  EXPECT_NE(alone.code, 0);
  EXPECT_NE(alone.output.find("--load-scale goes with --loads"), std::string::npos) << alone.output;
  const test::CommandOutcome mode = test::run_command(std::string(UNFURL_BINARY) + " render pantograph_compliant --mode 1 --loads --out " + (dir / "x").string());
  EXPECT_NE(mode.code, 0);
  EXPECT_NE(mode.output.find("no --trajectory, --plots or --loads"), std::string::npos) << mode.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace unfurl
