// unfurl render: frames (PNG), video (MP4 through ffmpeg) and plots of a
// run, headless (OSMesa: no display needed).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>

#include "cli.hpp"
#include "graphics_functions.hpp"
#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/gl_context.hpp"
#include "interrupt.hpp"
#include "modes_state.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/png_file.hpp"
#include "progress.hpp"
#include "render_options.hpp"
#include "scene_options.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/io/run_files.hpp"
#include "unfurl/render/load_arrows.hpp"
#include "unfurl/render/plot_renderer.hpp"
#include "unfurl/render/torque_margin_plot.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/io/video_pipe.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl render [SCENE] [--out DIR] [--fps 30] [--size 1280x720] [--from T0] [--to T1]\n"
    "                     [--video FILE.mp4] [--camera NAME|AZ,EL,DIST] [--orthographic] [--plots] [--no-frames]\n"
    "                     [--camera-frame bus|inertial] [--loads [--load-scale F]] [--exaggerate X]\n"
    "                     [--trajectory FILE] [scene options]\n"
    "       unfurl render [SCENE] --mode K [--mode-amplitude A] [--mode-period P] [--at T | --q ...]\n"
    "\n"
    "Simulates the scene (or reads a trajectory.csv written by `unfurl simulate`) and draws it\n"
    "offscreen: no display is needed.\n"
    "\n"
    "options:\n"
    "  --out DIR             where frames and plots go (default out)\n"
    "  --fps F               frames per second of simulated time (default 30)\n"
    "  --size WxH            picture size in pixels (default 1280x720)\n"
    "  --from T0, --to T1    the time span to draw (default: the whole run)\n"
    "  --video FILE.mp4      also encode the frames as an H.264 video (needs ffmpeg)\n"
    "  --camera VIEW         a preset (iso, side, top, end, bottom; default iso) or AZ,EL,DIST in\n"
    "                        degrees and metres around the centre of the array\n"
    "  --orthographic        parallel projection (with --camera side: a true view along the hinges)\n"
    "  --camera-frame F      with a free-floating bus: ride with the bus (bus, default) or stay in\n"
    "                        the inertial frame and watch the bus turn and drift (inertial)\n"
    "  --gl egl|osmesa|auto  the offscreen OpenGL context (default auto: EGL when it works, else\n"
    "                        OSMesa)\n"
    "  --plots               also write angles.png, rates.png, residuals.png (the loops' gaps;\n"
    "                        scenes with loops), loads.png, hinge_forces.png, energy.png, bus.png (a\n"
    "                        free-floating bus's attitude and rate), sensors.png and\n"
    "                        torque_margin.png (the driven joints' motorization factors)\n"
    "  --no-frames           do not write frame PNGs (with --video or --plots)\n"
    "  --loads               draw the loads as arrows: each joint's hinge force at its hinge point\n"
    "                        (green; grey where rigid loops leave it undetermined) and each engaged\n"
    "                        latch's torque along its axis (violet, double-headed, right-hand rule),\n"
    "                        the run's largest of each a quarter of the array's size; the legend\n"
    "                        gives them in N and N m\n"
    "  --load-scale F        arrows F times as long (default 1)\n"
    "  --exaggerate X        flexible bodies drawn bending X times their elastic displacement\n"
    "                        (default 1)\n"
    "  --trajectory FILE     draw this trajectory.csv instead of simulating (events.csv and\n"
    "                        loads.csv beside it give the latch marks and the loads plot); SCENE\n"
    "                        must be the scene it was made from\n"
    "  --mode K              draw mode K (1, 2, ... as `unfurl modes` lists them) instead of a run:\n"
    "                        one cycle of q(t) = q_eq + A sin(2 pi t / P) shape, labelled with its\n"
    "                        frequency and damping\n"
    "  --mode-amplitude A    the shape's largest coordinate, rad (default 0.1)\n"
    "  --mode-period P       seconds per drawn cycle, whatever the frequency (default 2)\n"
    "%s"
    "%s"
    "\n"
    "Frames are frame_00000.png, ... at t = T0 + k / F, interpolated from the trajectory.\n";

// Removes frame_NNNNN.png files of an earlier, longer render.
void remove_stale_frames(const std::string& dir, std::size_t written) {
  const std::regex pattern("frame_([0-9]{5,})\\.png");
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, pattern) && std::stoul(m[1]) >= written) std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace

int render_command(const std::vector<std::string>& argv) {
  std::set<std::string> valued = scene_flags();
  valued.insert(
      {"--out", "--fps", "--size", "--from", "--to", "--video", "--camera", "--camera-frame", "--trajectory", "--gl",
       "--mode", "--mode-amplitude", "--mode-period", "--load-scale", "--exaggerate"});
  valued.insert(modes_state_flags().begin(), modes_state_flags().end());
  std::set<std::string> switches{"--help", "-h", "--plots", "--no-frames", "--quiet", "--orthographic", "--loads"};
  switches.insert(modes_state_switches().begin(), modes_state_switches().end());
  const Args args(argv, valued, switches);
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp, modes_state_help(), scene_flags_help());
    return 0;
  }
  if (args.positionals().size() > 1) throw UsageError("render takes one SCENE (see --help)");
  const sim::SceneFile file =
      read_scene(args.positionals().empty() ? std::nullopt : std::optional(args.positionals()[0]), args);
  const sim::Scene& scene = file.scene;
  const RenderOptions options = parse_render_options(args);
  const std::string dir = args.get("--out").value_or("out");
  io::make_directory(dir);
  const bool quiet = args.has("--quiet");

  int exit_code = 0;
  // Ctrl+C stops the simulation or the frames where they are; what was
  // computed is drawn and the video is finished with the frames so far.
  const InterruptScope interrupt;
  sim::Trajectory trajectory;
  std::string caption;  // a mode's, in place of the time
  const bool mode = args.has("--mode");
  if (!mode && (args.has("--mode-amplitude") || args.has("--mode-period") || args.has("--at") || args.has("--q")))
    throw UsageError("--mode-amplitude, --mode-period, --at and --q go with --mode");
  if (mode && (args.has("--trajectory") || args.has("--plots") || options.loads))
    throw UsageError("--mode draws a mode, not a run: no --trajectory, --plots or --loads");
  if (mode) {
    const double k = args.number("--mode", 0), amplitude = args.number("--mode-amplitude", 0.1),
                 period = args.number("--mode-period", 2);
    if (!(k >= 1) || k != std::floor(k)) throw UsageError("--mode expects a mode number 1, 2, ...");
    if (!(amplitude > 0) || !(period > 0)) throw UsageError("--mode-amplitude and --mode-period expect numbers > 0");
    sim::ModesResult modes;
    std::string described;
    if (const int code = scene_modes(scene, args, modes, described)) return code;
    if (k > static_cast<double>(modes.modes.size()))
      throw UsageError("--mode " + std::to_string(static_cast<int>(k)) + ": the scene has " +
                       std::to_string(modes.modes.size()) + " modes");
    const sim::Mode& m = modes.modes[static_cast<int>(k) - 1];
    trajectory = sim::mode_animation(scene, modes, static_cast<int>(k) - 1, amplitude, period, 240);
    char text[128];
    if (m.kind == sim::ModeKind::elastic)
      std::snprintf(text, sizeof text, "mode %d: %.4g Hz, damping %.3g", static_cast<int>(k), m.frequency_hz,
                    m.damping_ratio);
    else
      std::snprintf(text, sizeof text, "mode %d: %s", static_cast<int>(k), sim::mode_kind_name(m.kind));
    caption = text;
  } else if (const auto path = args.get("--trajectory")) {
    trajectory = io::read_trajectory_csv(scene, *path);
  } else {
    Progress progress("simulating " + scene.name, scene.run.t_end);
    sim::RunObserver observer;
    observer.cancel = &interrupt.flag();
    if (!quiet) observer.on_progress = [&](const sim::StepProgress& p) { progress.update(p.t); };
    sim::RunResult run = sim::simulate(scene, scene.run, observer);
    progress.finish();
    if (run.status == sim::RunStatus::failed) {
      std::fprintf(stderr, "unfurl render: %s\n(drawing what was computed, up to t = %g s)\n",
                   sim::describe(run.failure).c_str(), run.trajectory.t_end());
      exit_code = 1;
    }
    trajectory = std::move(run.trajectory);
  }

  // Frames only where they go somewhere: --no-frames without a video draws none.
  const bool write_frames = !args.has("--no-frames");
  const std::vector<double> times = write_frames || options.video
                                        ? frame_times(options, trajectory.t_begin(), trajectory.t_end())
                                        : std::vector<double>{};
  auto context = render::make_offscreen_context(options.gl);
  render::FrameRenderer renderer(scene, file.visuals, options.width, options.height, mesh_directories(scene));
  const Eigen::AlignedBox3f bounds = motion_bounds(options, scene, trajectory, renderer.view());
  const render::Camera camera = choose_camera(options, bounds, static_cast<float>(options.width) / options.height);
  const render::LoadArrowScale arrow_scale =
      render::load_arrow_scale(scene, trajectory, bounds.diagonal().norm(), options.load_scale);
  const std::string legend = options.loads ? render::load_arrow_legend(arrow_scale) : "";
  if (options.loads && !(arrow_scale.peak_force > 0) && !(arrow_scale.peak_torque > 0))
    std::fprintf(stderr, "unfurl render: --loads: the run has no hinge forces or latch torques to draw%s\n",
                 args.has("--trajectory") ? " (loads.csv beside the trajectory gives them)" : "");

  std::unique_ptr<io::VideoPipe> video;
  if (options.video) {
    video = std::make_unique<io::VideoPipe>(*options.video, options.width, options.height, options.fps);
    if (!video->note().empty()) std::fprintf(stderr, "unfurl render: %s\n", video->note().c_str());
  }
  Progress progress("rendering " + std::to_string(times.size()) + " frames", static_cast<double>(times.size()));
  render::Image image;
  std::vector<double> q;
  std::vector<sim::Pose> poses;
  const auto start = std::chrono::steady_clock::now();
  std::size_t drawn = 0;
  for (std::size_t k = 0; k < times.size() && !interrupt.flag().load(); ++k, ++drawn) {
    trajectory.coordinates_at(times[k], q);
    render::poses_in_camera_frame(options.camera_frame, scene.model, q.data(), poses);
    renderer.deform(scene.model, q.data(), options.exaggerate);
    std::vector<render::LoadArrow> arrows;
    if (options.loads)
      arrows = render::load_arrows(scene, trajectory, trajectory.sample_at(times[k]), poses, arrow_scale);
    renderer.frame(poses, caption.empty() ? render::time_caption(times[k]) : caption, camera, image, arrows, legend);
    if (write_frames) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05zu.png", k);
      io::write_png(image, dir + name);
    }
    if (video) video->add(image);
    if (!quiet) progress.update(static_cast<double>(k + 1));
  }
  progress.finish();
  if (write_frames) remove_stale_frames(dir, drawn);
  if (video) video->finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::string> plots;
  if (args.has("--plots")) {
    render::PlotRenderer plotter(options.width, options.height);
    for (const render::NamedPlot& p : render::trajectory_plots(scene, trajectory)) {
      plotter.draw(p.spec, image);
      io::write_png(image, dir + "/" + p.file, 6);
      plots.push_back(dir + "/" + p.file);
    }
    if (const auto margins = sim::torque_margins(scene, trajectory); !margins.empty()) {
      plotter.draw(render::torque_margin_plot(scene.name, margins, scene.torque_margin), image);
      io::write_png(image, dir + "/torque_margin.png", 6);
      plots.push_back(dir + "/torque_margin.png");
    }
  }

  if (!quiet) {
    std::printf("scene        %s (%s)\n", scene.name.c_str(), scene.source.c_str());
    std::printf("context      %s\n", context->description().c_str());
    if (times.empty())
      std::printf("frames       none drawn (--no-frames and no --video)\n");
    else
      std::printf("frames       %zu at %g fps, t = %g .. %g s, %dx%d, %.1f frames/s%s\n", times.size(), options.fps,
                  times.front(), times.back(), options.width, options.height,
                  seconds > 0 ? times.size() / seconds : 0.0,
                  write_frames ? (", " + dir + "/frame_*.png").c_str() : " (not written)");
    if (video) std::printf("video        %s\n", options.video->c_str());
    for (const std::string& p : plots) std::printf("plot         %s\n", p.c_str());
  }
  if (interrupt.signal()) {
    std::fprintf(stderr, "unfurl render: interrupted by %s (%zu of %zu frames drawn, up to t = %g s computed)\n",
                 interrupt.signal_name(), drawn, times.size(), trajectory.t_end());
    return interrupt.exit_status();
  }
  return exit_code;
}

}  // namespace unfurl::app
