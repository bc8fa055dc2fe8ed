// Offscreen frames of the pantograph at 1280x720: draw plus read-back, and
// with PNG encoding (libpng level 1, as `unfurl render` writes frames).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "frame_renderer.hpp"
#include "gl_context.hpp"
#include "png_file.hpp"
#include "scene_yaml.hpp"

namespace unfurl {
namespace {

struct Setup {
  Scene scene = load_builtin_scene("pantograph");
  std::unique_ptr<render::GlContext> context = render::make_offscreen_context();
  render::FrameRenderer renderer{scene, 1280, 720, {render::builtin_mesh_directory()}};
  std::vector<Pose> poses;
  render::Camera camera;
  Setup() {
    std::vector<double> q(scene.model.nq);
    for (int c = 0; c < scene.model.nq; ++c) q[c] = 0.5 * scene.q0[c];  // mid-deployment
    body_poses(scene.model, q.data(), poses);
    camera = *render::camera_preset("iso", renderer.view().bounds(poses), 1280.0f / 720);
  }
};

void BM_FrameRenderAndReadback(benchmark::State& state) {
  Setup s;
  render::Image image;
  for (auto _ : state) s.renderer.frame(s.poses, 1.0, s.camera, image);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameRenderAndReadback)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FrameRenderReadbackAndPng(benchmark::State& state) {
  Setup s;
  render::Image image;
  const std::string path = (std::filesystem::temp_directory_path() / "unfurl_bench_frame.png").string();
  for (auto _ : state) {
    s.renderer.frame(s.poses, 1.0, s.camera, image);
    app::write_png(image, path);
  }
  std::filesystem::remove(path);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameRenderReadbackAndPng)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace unfurl
