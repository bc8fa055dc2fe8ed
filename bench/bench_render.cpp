// Offscreen frames of the pantograph at 1280x720: draw plus read-back, and
// with PNG encoding (libpng level 1, as `unfurl render` writes frames); each
// through every offscreen GL backend the build has (EGL, OSMesa).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/mesh_file.hpp"
#include "unfurl/render/gl_context.hpp"
#include "unfurl/io/png_file.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace unfurl {
namespace {

struct Setup {
  explicit Setup(render::GlBackend backend) : context(render::make_offscreen_context(backend)) { place(); }
  sim::SceneFile file = sim::read_builtin_scene("pantograph");
  sim::Scene& scene = file.scene;
  std::unique_ptr<render::GlContext> context;
  render::FrameRenderer renderer{scene, file.visuals, 1280, 720, {render::builtin_mesh_directory()}};
  std::vector<sim::Pose> poses;
  render::Camera camera;
  void place() {
    std::vector<double> q(scene.model.nq);
    for (int c = 0; c < scene.model.nq; ++c) q[c] = 0.5 * scene.q0[c];  // mid-deployment
    sim::body_poses(scene.model, q.data(), poses);
    camera = *render::camera_preset("iso", renderer.view().bounds(poses), 1280.0f / 720);
  }
};

render::GlBackend backend_of(const benchmark::State& state) {
  return render::available_gl_backends().at(static_cast<std::size_t>(state.range(0)));
}

void label_backend(benchmark::State& state) { state.SetLabel(render::gl_backend_name(backend_of(state))); }

// One argument per backend the build has: 0 .. n-1.
void each_backend(benchmark::internal::Benchmark* b) {
  for (std::size_t k = 0; k < render::available_gl_backends().size(); ++k) b->Arg(static_cast<int>(k));
}

void BM_FrameRenderAndReadback(benchmark::State& state) {
  Setup s(backend_of(state));
  label_backend(state);
  render::Image image;
  for (auto _ : state) s.renderer.frame(s.poses, 1.0, s.camera, image);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameRenderAndReadback)->Apply(each_backend)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FrameRenderReadbackAndPng(benchmark::State& state) {
  Setup s(backend_of(state));
  label_backend(state);
  render::Image image;
  const std::string path = (std::filesystem::temp_directory_path() / "unfurl_bench_frame.png").string();
  for (auto _ : state) {
    s.renderer.frame(s.poses, 1.0, s.camera, image);
    io::write_png(image, path);
  }
  std::filesystem::remove(path);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameRenderReadbackAndPng)->Apply(each_backend)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace unfurl
