#include "render_options.hpp"

#include <cmath>
#include <sstream>
#include <tuple>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/render/mesh_library.hpp"

namespace unfurl::app {

std::pair<int, int> parse_pixel_size(const std::string& flag, const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || x != 'x' || (in >> extra) || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw UsageError(flag + ": expected WxH between 16x16 and 8192x8192, got '" + text + "'");
  return {w, h};
}

RenderOptions parse_render_options(const Args& args) {
  RenderOptions o;
  o.fps = args.number("--fps", o.fps);
  if (!(o.fps > 0) || o.fps > 10000) throw UsageError("--fps: must be between 0 and 10000");
  if (const auto size = args.get("--size")) std::tie(o.width, o.height) = parse_pixel_size("--size", *size);
  o.from = args.number("--from");
  o.to = args.number("--to");
  if (o.from && o.to && *o.to < *o.from) throw UsageError("--to must not be before --from");
  o.video = args.get("--video");
  o.camera = args.get("--camera").value_or(o.camera);
  o.orthographic = args.has("--orthographic");
  if (const auto frame = args.get("--camera-frame")) {
    const auto parsed = render::parse_camera_frame(*frame);
    if (!parsed) throw UsageError("--camera-frame: expected bus or inertial, got '" + *frame + "'");
    o.camera_frame = *parsed;
  }
  if (const auto gl = args.get("--gl")) {
    const auto backend = render::parse_gl_backend(*gl);
    if (!backend) throw UsageError("--gl: expected egl, osmesa or auto, got '" + *gl + "'");
    o.gl = *backend;
  }
  o.loads = args.has("--loads");
  if (args.has("--load-scale")) {
    if (!o.loads) throw UsageError("--load-scale goes with --loads");
    const double scale = args.number("--load-scale", 1);
    if (!(scale > 0) || scale > 1000) throw UsageError("--load-scale: expected a factor between 0 and 1000");
    o.load_scale = static_cast<float>(scale);
  }
  if (args.has("--exaggerate")) {
    o.exaggerate = args.number("--exaggerate", 1);
    if (!(o.exaggerate > 0) || o.exaggerate > 1e6) throw UsageError("--exaggerate: expected a factor between 0 and 1e6");
  }
  return o;
}

std::vector<double> frame_times(const RenderOptions& options, double t_begin, double t_end) {
  const double t0 = std::max(t_begin, options.from.value_or(t_begin));
  const double t1 = std::min(t_end, options.to.value_or(t_end));
  std::vector<double> times;
  if (t1 < t0) return times;
  const long count = static_cast<long>(std::floor((t1 - t0) * options.fps + 1e-9)) + 1;
  for (long k = 0; k < count; ++k) times.push_back(t0 + k / options.fps);
  return times;
}

Eigen::AlignedBox3f motion_bounds(const RenderOptions& options, const sim::Scene& scene,
                                  const sim::Trajectory& trajectory, const render::SceneView& view) {
  // Everything the mechanism sweeps through, from about 200 samples.
  Eigen::AlignedBox3f bounds;
  std::vector<double> q;
  std::vector<sim::Pose> poses;
  const std::size_t stride = std::max<std::size_t>(1, trajectory.samples.size() / 200);
  for (std::size_t k = 0; k < trajectory.samples.size(); k += stride) {
    trajectory.coordinates_at(trajectory.samples[k].t, q);
    render::poses_in_camera_frame(options.camera_frame, scene.model, q.data(), poses);
    bounds.extend(view.bounds(poses));
  }
  trajectory.coordinates_at(trajectory.t_end(), q);
  render::poses_in_camera_frame(options.camera_frame, scene.model, q.data(), poses);
  bounds.extend(view.bounds(poses));
  return bounds;
}

render::Camera choose_camera(const RenderOptions& options, const Eigen::AlignedBox3f& bounds, float aspect) {
  if (auto preset = render::camera_preset(options.camera, bounds, aspect)) {
    preset->orthographic = options.orthographic;
    return *preset;
  }
  std::istringstream in(options.camera);
  render::Camera c;
  c.orthographic = options.orthographic;
  char comma1 = 0, comma2 = 0;
  if (!(in >> c.azimuth_deg >> comma1 >> c.elevation_deg >> comma2 >> c.distance) || comma1 != ',' || comma2 != ',' ||
      !(c.distance > 0)) {
    std::string names;
    for (const auto& n : render::camera_preset_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("--camera: expected a preset (" + names + ") or AZ,EL,DIST, got '" + options.camera + "'");
  }
  c.target = bounds.center();
  return c;
}

}  // namespace unfurl::app
