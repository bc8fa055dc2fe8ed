// Headless rendering: pixels of an offscreen frame, frame times, repeatable
// pictures, plots inside their axes, and the video's frame count.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <set>

#include "unfurl/render/camera_frame.hpp"
#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/plot_renderer.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "png_read.hpp"
#include "unfurl/render/gl_context.hpp"
#include "unfurl/render/mesh_file.hpp"
#include "unfurl/render/mesh_generator.hpp"
#include "render_options.hpp"
#include "support.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/io/video_pipe.hpp"

namespace unfurl {
namespace {

using render::Image;

// One GL context for the whole test program.
class Render : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = render::make_offscreen_context().release(); }
  static void TearDownTestSuite() { delete context_; }
  static render::GlContext* context_;
};
render::GlContext* Render::context_ = nullptr;

// The pixel where a base-frame point projects.
std::pair<int, int> project(const render::Camera& camera, const Eigen::Vector3f& p, int w, int h) {
  const Eigen::Vector4f c = camera.projection(static_cast<float>(w) / h) * camera.view() * p.homogeneous();
  const float x = c.x() / c.w(), y = c.y() / c.w();
  return {static_cast<int>((x + 1) / 2 * w), static_cast<int>((1 - y) / 2 * h)};
}

std::vector<sim::Pose> deployed_poses(const sim::Scene& scene) {
  std::vector<double> q(scene.model.nq, 0.0);
  std::vector<sim::Pose> poses;
  sim::body_poses(scene.model, q.data(), poses);
  return poses;
}

TEST_F(Render, DeployedPantographFromAbove) {
  const sim::SceneFile file = sim::read_scene_file(test::asset("scenes/pantograph.yaml"));
  const sim::Scene& scene = file.scene;
  const int w = 320, h = 180;
  render::FrameRenderer renderer(scene, file.visuals, w, h, {render::builtin_mesh_directory()});
  const std::vector<sim::Pose> poses = deployed_poses(scene);
  const render::Camera camera = *render::camera_preset("top", renderer.view().bounds(poses), float(w) / h);
  Image image;
  renderer.frame(poses, 0, camera, image);
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);

  // Not blank: many distinct colours.
  std::set<int> colours;
  for (std::size_t k = 0; k < image.rgb.size(); k += 3)
    colours.insert(image.rgb[k] << 16 | image.rgb[k + 1] << 8 | image.rgb[k + 2]);
  EXPECT_GT(colours.size(), 100u);

  // The panel colour (the blue cells) at panel B2's centre, on its front
  // face (+z, towards the camera).
  const int b2 = *scene.model.find_body("panel_B2");
  const Eigen::Vector3f centre = poses[b2].to_base(sim::Vec3(0.1, 0.1, 0.0125)).cast<float>();
  const auto [px, py] = project(camera, centre, w, h);
  const std::uint8_t* c = image.pixel(px, py);
  EXPECT_GT(c[2], c[0] + 40) << "at " << px << "," << py << ": " << int(c[0]) << " " << int(c[1]) << " " << int(c[2]);
  EXPECT_GT(c[2], c[1] + 20);

  // The background where nothing is: the bottom-left corner is the
  // gradient's grey-blue.
  const std::uint8_t* bg = image.pixel(w - 3, h - 3);
  EXPECT_NEAR(bg[0], 77, 12);
  EXPECT_NEAR(bg[1], 87, 12);
  EXPECT_NEAR(bg[2], 107, 12);
}

// A flexible beam drawn bent: the spin-up beam, seen from above, with one
// bending mode displacing its tip 2 m across; the bent beam covers the
// bent point and leaves the straight one, and undeformed it is the other
// way round.
TEST_F(Render, AFlexibleBeamIsDrawnBent) {
  const sim::SceneFile file = sim::read_builtin_scene("spinup_beam");
  const sim::Scene& scene = file.scene;
  const sim::Model& model = scene.model;
  const int w = 320, h = 320, beam = *model.find_body("beam");
  const sim::flexible::FlexibleBody& flexible = *model.bodies[beam].flexible;
  const sim::flexible::FlexibleNode& node = flexible.mesh_nodes[flexible.mesh_nodes.size() - 2];  // near the tip
  int k = 0;
  for (int j = 0; j < flexible.modes(); ++j)
    if (std::abs(node.shape(1, j)) > std::abs(node.shape(1, k))) k = j;
  std::vector<double> straight(model.nq, 0.0), bent = straight;
  bent[model.first_elastic_position[beam] + k] = 2.0 / node.shape(1, k);
  const Eigen::Vector3d moved = node.shape.topRows<3>().col(k) * bent[model.first_elastic_position[beam] + k];
  render::FrameRenderer renderer(scene, file.visuals, w, h, {render::builtin_mesh_directory()});
  std::vector<sim::Pose> poses;
  sim::body_poses(model, straight.data(), poses);
  const render::Camera camera = *render::camera_preset("top", renderer.view().bounds(poses), float(w) / h);
  const auto brightness = [&](const std::vector<double>& q, const sim::Vec3& p) {
    Image image;
    renderer.deform(model, q.data(), 1.0);
    renderer.frame(poses, 0, camera, image);
    const auto [px, py] = project(camera, poses[beam].to_base(p).cast<float>(), w, h);
    const std::uint8_t* c = image.pixel(px, py);
    return c[0] + c[1] + c[2];
  };
  const sim::Vec3 at_rest = node.point, displaced = node.point + sim::Vec3(moved.x(), moved.y(), 0);
  EXPECT_GT(brightness(straight, at_rest), brightness(straight, displaced) + 150);
  EXPECT_GT(brightness(bent, displaced), brightness(bent, at_rest) + 150);
}

TEST_F(Render, SameFrameTwiceGivesIdenticalPixels) {
  const sim::SceneFile file = sim::read_scene_file(test::asset("scenes/zfold.yaml"));
  const sim::Scene& scene = file.scene;
  render::FrameRenderer renderer(scene, file.visuals, 200, 120, {render::builtin_mesh_directory()});
  std::vector<double> q = scene.q0;
  std::vector<sim::Pose> poses;
  sim::body_poses(scene.model, q.data(), poses);
  const render::Camera camera = *render::camera_preset("iso", renderer.view().bounds(poses), 200.0f / 120);
  Image a, b;
  renderer.frame(poses, 1.5, camera, a);
  renderer.frame(poses, 1.5, camera, b);
  EXPECT_EQ(a.rgb, b.rgb);
}

// Pixels of one colour in a picture, inside and outside the axes' box.
struct ColourCount {
  int inside = 0, outside = 0;
  std::set<int> columns;  // that hold some of it inside
};

ColourCount count_colour(const Image& image, const render::PlotFrame& frame, ImU32 colour) {
  const int r = colour & 0xFF, g = (colour >> 8) & 0xFF, b = (colour >> 16) & 0xFF;
  ColourCount n;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (std::abs(p[0] - r) > 12 || std::abs(p[1] - g) > 12 || std::abs(p[2] - b) > 12) continue;
      const bool in = x >= frame.plot_min.x - 1 && x <= frame.plot_max.x + 1 && y >= frame.plot_min.y - 1 &&
                      y <= frame.plot_max.y + 1;
      if (in) n.columns.insert(x);
      (in ? n.inside : n.outside)++;
    }
  return n;
}

TEST_F(Render, AnglePlotOfARunKeepsItsCurvesInsideTheAxes) {
  // The z-fold's joint-angle plot (the paper's figure 6) as `render --plots`
  // draws it. j4's curve (palette colour 3) is drawn last, on top of the
  // others where they meet at the deployed 0, so it shows along the whole run.
  const sim::Scene scene = test::scene_file("zfold", {{"run.t_end", "10"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const render::PlotSpec spec = render::trajectory_plot(render::PlotKind::angles, scene, run.trajectory);
  render::PlotRenderer plotter(640, 360);
  Image image;
  const render::PlotFrame frame = plotter.draw(spec, image);
  const ColourCount n = count_colour(image, frame, render::palette(3));
  EXPECT_GT(n.inside, 300);
  EXPECT_EQ(n.outside, 0);
  // The whole run is drawn: the curve reaches across the axes.
  EXPECT_GE(static_cast<int>(n.columns.size()), static_cast<int>(0.9 * (frame.plot_max.x - frame.plot_min.x)));
  // The axes hold the data: from j3's -pi to j2's and j4's pi.
  EXPECT_LE(frame.y_min, -M_PI / 2);
  EXPECT_GE(frame.y_max, M_PI);
  EXPECT_DOUBLE_EQ(frame.x_max, 10.0);
}

TEST_F(Render, LoadsPlotShadesWhereTheLoadsAreIndeterminate) {
  // The pantograph's loads are determinate until its latch-up at 7.392 s,
  // where the loops reach their deployed branch point; the plot shades the
  // samples (every 0.01 s) whose loads are not, from 7.43 s on (the
  // latch-up's own peak at 7.400 s is determinate).
  const sim::Scene scene = test::scene_file("pantograph", {{"run.t_end", "8"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const render::PlotSpec spec = render::trajectory_plot(render::PlotKind::loads, scene, run.trajectory);
  ASSERT_FALSE(spec.shaded.empty());
  EXPECT_GT(spec.shaded.front().first, 7.38);
  EXPECT_LT(spec.shaded.front().first, 7.45);
  EXPECT_DOUBLE_EQ(spec.shaded.back().second, 8.0);
  render::PlotRenderer plotter(640, 360);
  Image image;
  const render::PlotFrame frame = plotter.draw(spec, image);
  const auto pixel = [&](double t) {
    const ImVec2 at = frame.to_screen(t, 0);
    return image.pixel(static_cast<int>(at.x), static_cast<int>(frame.plot_min.y) + 3);
  };
  const std::uint8_t* before = pixel(3.3);
  const std::uint8_t* inside = pixel(7.7);
  EXPECT_EQ(before[0] + before[1] + before[2], 3 * 255);  // the white background
  EXPECT_LT(inside[2], 235);                              // shaded amber
  EXPECT_GT(inside[0], inside[2]);
}

TEST_F(Render, LogLogPlotPlacesDecadesAndMarkers) {
  render::PlotSpec spec;
  spec.title = "error against run time";
  spec.log_x = spec.log_y = true;
  render::Series s;
  s.label = "power law";
  s.color = IM_COL32(220, 20, 20, 255);
  s.markers = true;
  for (double x : {1e-3, 1e-2, 1e-1, 1.0}) {
    s.x.push_back(x);
    s.y.push_back(1e-4 / (x * x));
  }
  spec.series.push_back(s);
  render::PlotRenderer plotter(640, 360);
  Image image;
  const render::PlotFrame frame = plotter.draw(spec, image);
  EXPECT_DOUBLE_EQ(frame.x_min, -3);
  EXPECT_DOUBLE_EQ(frame.x_max, 0);
  EXPECT_DOUBLE_EQ(frame.y_min, -4);
  EXPECT_DOUBLE_EQ(frame.y_max, 2);
  // A straight line in log-log: the middle points sit on the chord.
  const ImVec2 a = frame.to_screen(1e-3, 1e2), b = frame.to_screen(1.0, 1e-4), m = frame.to_screen(1e-2, 1.0);
  EXPECT_NEAR(m.y, a.y + (b.y - a.y) * (m.x - a.x) / (b.x - a.x), 0.5);
  const ColourCount n = count_colour(image, frame, s.color);
  EXPECT_EQ(n.outside, 0);
  EXPECT_GT(n.inside, 200);
}

TEST_F(Render, LegendLeavesTheDataVisible) {
  // Wall time against size: rising curves end in the top right corner, where
  // a legend would hide the largest runs. The legend moves to a free corner.
  render::PlotSpec spec;
  spec.title = "wall time against size";
  spec.log_x = spec.log_y = true;
  for (int i = 0; i < 6; ++i) {
    render::Series s;
    s.label = "a long label for method " + std::to_string(i);
    s.color = render::palette(i);
    s.markers = true;
    for (double n : {10.0, 100.0, 1000.0, 3000.0}) {
      s.x.push_back(n);
      s.y.push_back(1e-3 * n * (1 + 0.1 * i));
    }
    spec.series.push_back(s);
  }
  render::PlotRenderer plotter(640, 360);
  Image image;
  const render::PlotFrame frame = plotter.draw(spec, image);
  const render::Series& top = spec.series.back();
  const ImVec2 last = frame.to_screen(top.x.back(), top.y.back());
  const int r = top.color & 0xFF, g = (top.color >> 8) & 0xFF, b = (top.color >> 16) & 0xFF;
  int seen = 0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -4; dx <= 0; ++dx) {
      const std::uint8_t* p = image.pixel(static_cast<int>(last.x) + dx, static_cast<int>(last.y) + dy);
      seen += std::abs(p[0] - r) <= 12 && std::abs(p[1] - g) <= 12 && std::abs(p[2] - b) <= 12;
    }
  EXPECT_GT(seen, 3) << "the largest run's marker is hidden";
}

TEST(GlBackends, EglAndOsmesaDrawTheSameFrame) {
  // Two independent GL stacks (both llvmpipe here, through different
  // loaders): the same scene, pose and camera within a few grey levels.
  const std::vector<render::GlBackend> backends = render::available_gl_backends();
  ASSERT_FALSE(backends.empty());
  if (backends.size() < 2) GTEST_SKIP() << "this build has one offscreen backend";
  const sim::SceneFile file = sim::read_scene_file(test::asset("scenes/pantograph.yaml"));
  std::vector<double> q(file.scene.model.nq);
  for (int c = 0; c < file.scene.model.nq; ++c) q[c] = 0.5 * file.scene.q0[c];
  std::vector<sim::Pose> poses;
  sim::body_poses(file.scene.model, q.data(), poses);
  Image frames[2];
  for (int k = 0; k < 2; ++k) {
    auto context = render::make_offscreen_context(backends[k]);
    render::FrameRenderer renderer(file.scene, file.visuals, 320, 180, {render::builtin_mesh_directory()});
    const render::Camera camera = *render::camera_preset("iso", renderer.view().bounds(poses), 320.0f / 180);
    renderer.frame(poses, 1.0, camera, frames[k]);
  }
  ASSERT_EQ(frames[0].rgb.size(), frames[1].rgb.size());
  long total = 0;
  int largest = 0;
  for (std::size_t i = 0; i < frames[0].rgb.size(); ++i) {
    const int d = std::abs(int(frames[0].rgb[i]) - int(frames[1].rgb[i]));
    largest = std::max(largest, d);
    total += d;
  }
  EXPECT_LE(largest, 4) << "grey levels, the largest difference of any pixel channel";
  EXPECT_LT(static_cast<double>(total) / frames[0].rgb.size(), 0.5) << "grey levels, mean";
}

TEST(FrameTimes, RangeAndRate) {
  app::RenderOptions o;
  o.fps = 10;
  o.from = 1.0;
  o.to = 2.0;
  const auto t = app::frame_times(o, 0, 20);
  ASSERT_EQ(t.size(), 11u);
  EXPECT_DOUBLE_EQ(t.front(), 1.0);
  EXPECT_NEAR(t.back(), 2.0, 1e-12);
  EXPECT_NEAR(t[3], 1.3, 1e-12);
  o.from.reset();
  o.to.reset();
  o.fps = 30;
  EXPECT_EQ(app::frame_times(o, 0, 20).size(), 601u);  // both ends included
  o.to = 100;                                            // clamped to the run
  EXPECT_EQ(app::frame_times(o, 0, 20).size(), 601u);
}

TEST(Meshes, AssetsAreTheGeneratorsOutput) {
  for (const auto& [name, text] : render::builtin_mesh_files()) {
    EXPECT_EQ(test::text_of(test::asset("meshes/" + name)), text) << name << " differs from the generator: run build/render/unfurl_meshes assets/meshes";
  }
}

int run_command(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RenderCommand, WritesFramesPlotsAndAVideoWithTheExpectedFrameCount) {
  if (!io::on_path("ffmpeg") || !io::on_path("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("unfurl_render_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string video = (dir / "zfold.mp4").string();
  ASSERT_EQ(run_command(std::string(UNFURL_BINARY) + " render zfold --t-end 1 --fps 10 --size 320x180 --plots --quiet" +
                        " --video " + video + " --out " + dir.string()),
            0);
  for (int k = 0; k <= 10; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir / "frame_00011.png"));
  for (const char* plot : {"angles.png", "rates.png", "loads.png", "hinge_forces.png", "energy.png"})
    EXPECT_TRUE(fs::exists(dir / plot)) << plot;
  EXPECT_FALSE(fs::exists(dir / "residuals.png"));  // a tree has no loop gaps
  EXPECT_FALSE(fs::exists(dir / "bus.png"));        // nor a free bus
  const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                            "-of csv=p=0 " + video;
  FILE* pipe = popen(probe.c_str(), "r");
  char buf[64] = {0};
  ASSERT_NE(std::fgets(buf, sizeof buf, pipe), nullptr);
  pclose(pipe);
  EXPECT_EQ(std::atoi(buf), 11);
}

// Riding with a free bus holds the bus at the origin, unturned, and keeps
// every body where it is relative to the bus; the inertial frame is the
// solver's.
TEST(CameraFrame, RidingWithTheBusHoldsItStillAndKeepsTheArrayOnIt) {
  const sim::Scene scene = sim::load_builtin_scene("zfold_free", {{"run.t_end", "6"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  ASSERT_EQ(run.status, sim::RunStatus::finished);
  const std::vector<double> q(run.trajectory.samples.back().y.begin(),
                              run.trajectory.samples.back().y.begin() + scene.model.nq);
  std::vector<sim::Pose> riding, inertial, solver;
  render::poses_in_camera_frame(render::CameraFrame::bus, scene.model, q.data(), riding);
  render::poses_in_camera_frame(render::CameraFrame::inertial, scene.model, q.data(), inertial);
  sim::body_poses(scene.model, q.data(), solver);
  EXPECT_LT(riding[0].position.norm(), 1e-15);
  EXPECT_LT((riding[0].rotation - sim::Mat3::Identity()).norm(), 1e-15);
  EXPECT_GT(Eigen::AngleAxisd(inertial[0].rotation).angle(), 0.05) << "the bus has turned by t = 6 s";
  for (int i = 0; i < scene.model.size(); ++i) {
    EXPECT_EQ(inertial[i].position, solver[i].position);
    // Body i seen from the bus: the same either way.
    const sim::Vec3 seen = inertial[0].rotation * (inertial[i].position - inertial[0].position);
    EXPECT_LT((riding[i].position - seen).norm(), 1e-12);
    EXPECT_LT((riding[i].rotation - inertial[i].rotation * inertial[0].rotation.transpose()).norm(), 1e-12);
  }
}

// A free-floating bus: its attitude plot, and frames from the inertial
// frame that differ from those riding with the bus once it has turned.
TEST(RenderCommand, AFreeBusGetsItsPlotAndTheCameraFrameMatters) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("unfurl_render_free_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string common = std::string(UNFURL_BINARY) + " render zfold_free --t-end 4 --from 4 --to 4 --size 320x180 --quiet";
  ASSERT_EQ(run_command(common + " --plots --out " + (dir / "bus").string()), 0);
  ASSERT_EQ(run_command(common + " --camera-frame inertial --out " + (dir / "inertial").string()), 0);
  EXPECT_TRUE(fs::exists(dir / "bus" / "bus.png"));
  const render::Image riding = test::read_png((dir / "bus" / "frame_00000.png").string());
  const render::Image inertial = test::read_png((dir / "inertial" / "frame_00000.png").string());
  EXPECT_NE(riding.rgb, inertial.rgb);
  EXPECT_NE(run_command(common + " --camera-frame nowhere --out " + (dir / "bad").string()), 0);
  fs::remove_all(dir);
}

// H.264 needs even sizes: an odd one is padded by a pixel and said so, not a
// silent exit 141 (SIGPIPE) with .partial files left behind.
TEST(RenderCommand, OddVideoSizeIsPaddedAndSaid) {
  if (!io::on_path("ffmpeg") || !io::on_path("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("unfurl_render_odd_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string video = (dir / "odd.mp4").string();
  const test::CommandOutcome o = test::run_command(std::string(UNFURL_BINARY) +
                                                   " render pendulum --t-end 0.5 --fps 10 --size 641x361 --no-frames"
                                                   " --quiet --video " + video + " --out " + dir.string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("the video is 642x362"), std::string::npos) << o.output;
  FILE* pipe = popen(("ffprobe -v error -show_entries stream=width,height -of csv=p=0 " + video).c_str(), "r");
  char buf[64] = {0};
  ASSERT_NE(std::fgets(buf, sizeof buf, pipe), nullptr);
  pclose(pipe);
  EXPECT_EQ(std::string(buf), "642,362\n");
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace unfurl
