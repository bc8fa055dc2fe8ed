// What `unfurl render` (and the GUI's export) needs besides the scene: the
// frame size and rate, the time span, the camera, the video file.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "unfurl/render/camera.hpp"
#include "unfurl/render/camera_frame.hpp"
#include "unfurl/render/gl_context.hpp"
#include "cli.hpp"
#include "mesh_directories.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/render/scene_view.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::app {

struct RenderOptions {
  double fps = 30;
  int width = 1280, height = 720;
  std::optional<double> from, to;
  std::optional<std::string> video;
  std::string camera = "iso";  // a preset or "AZ,EL,DIST"
  bool orthographic = false;   // parallel projection
  // A free-floating bus: ride with it (default) or stay inertial.
  render::CameraFrame camera_frame = render::CameraFrame::bus;
  render::GlBackend gl = render::GlBackend::automatic;
  // Hinge forces and latch torques drawn as arrows (load_arrows.hpp), each
  // kind's largest `load_scale` times the default length.
  bool loads = false;
  float load_scale = 1;
  // Flexible bodies' elastic displacements drawn this many times.
  double exaggerate = 1;
};

// "WxH" in pixels, 16 to 8192 each; throws UsageError naming the flag.
std::pair<int, int> parse_pixel_size(const std::string& flag, const std::string& text);

// From --fps, --size, --from, --to, --video, --camera, --gl, --loads,
// --load-scale, --exaggerate; throws UsageError.
RenderOptions parse_render_options(const Args& args);

// t = T0 + k / fps for k = 0, 1, ... up to T1, within [t_begin, t_end].
std::vector<double> frame_times(const RenderOptions& options, double t_begin, double t_end);

// Everything the run sweeps through, as the view draws it.
Eigen::AlignedBox3f motion_bounds(const RenderOptions& options, const sim::Scene& scene,
                                  const sim::Trajectory& trajectory, const render::SceneView& view);

// The camera the options ask for, fitted to `bounds` (motion_bounds).
render::Camera choose_camera(const RenderOptions& options, const Eigen::AlignedBox3f& bounds, float aspect);

}  // namespace unfurl::app
