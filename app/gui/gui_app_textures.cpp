// The 3D view and the plots as textures, drawn again only when what they
// show changed (their keys).
#include "gui_app.hpp"

#include "gui_clock.hpp"
#include "gui_panels.hpp"
#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/window_surface.hpp"

namespace unfurl::app {

void GuiApp::current_coordinates(std::vector<double>& q) const {
  q = state_.scene.q0;
  if (state_.modes.shown >= 0)
    state_.modes.animation.coordinates_at(state_.modes.clock, q);
  else if (!state_.trajectory.empty())
    state_.trajectory.coordinates_at(state_.play_time, q);
}

void GuiApp::current_poses(std::vector<sim::Pose>& poses) const {
  std::vector<double> q;
  current_coordinates(q);
  render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, q.data(), poses);
}

std::vector<render::LoadArrow> GuiApp::current_load_arrows(const std::vector<sim::Pose>& poses,
                                                           std::string& legend) const {
  legend.clear();
  const std::optional<render::LoadArrowScale> scale = load_arrow_scale();
  if (!scale) return {};
  legend = render::load_arrow_legend(*scale);
  const sim::Trajectory& tr = state_.trajectory;
  return render::load_arrows(state_.scene, tr, tr.sample_at(state_.play_time), poses, *scale);
}

std::optional<render::LoadArrowScale> GuiApp::load_arrow_scale() const {
  if (!state_.show_loads || state_.modes.shown >= 0 || state_.trajectory.empty()) return std::nullopt;
  return render::load_arrow_scale(state_.scene, state_.trajectory, swept_bounds().diagonal().norm(),
                                  state_.load_scale);
}

Eigen::AlignedBox3f GuiApp::swept_bounds() const {
  Eigen::AlignedBox3f bounds;
  std::vector<sim::Pose> poses;
  render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, state_.scene.q0.data(), poses);
  bounds.extend(view_->bounds(poses));
  const sim::Trajectory& tr = state_.trajectory;
  const std::size_t stride = std::max<std::size_t>(1, tr.samples.size() / 100);
  std::vector<double> q;
  for (std::size_t k = 0; k < tr.samples.size(); k += stride) {
    q.assign(tr.samples[k].y.begin(), tr.samples[k].y.begin() + state_.scene.model.nq);
    render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, q.data(), poses);
    bounds.extend(view_->bounds(poses));
  }
  return bounds;
}

void GuiApp::draw_viewport_texture() {
  const int w = std::max(16, state_.viewport_width), h = std::max(16, state_.viewport_height);
  if (!viewport_ || viewport_->width() != w || viewport_->height() != h) {
    viewport_ = std::make_unique<render::Framebuffer>(w, h);
    viewport_drawn_ = false;
  }
  // Frame the whole motion until the first run is done (or after "reset"),
  // twice a second while it streams in: each refit redraws the view.
  const bool run_done = state_.run_settled();
  if (!state_.camera_fitted && (run_done || now_seconds() - camera_fitted_at_ >= 0.5)) {
    camera_fitted_at_ = now_seconds();
    const bool orthographic = state_.camera.orthographic;
    state_.camera = *render::camera_preset("iso", swept_bounds(), float(w) / h);
    state_.camera.orthographic = orthographic;
    state_.camera_name = "iso";
    state_.camera_fitted = run_done;
  }
  // Redrawn only when what it shows changed: while a run computes, a
  // software renderer would otherwise spend a core redrawing a still view.
  const render::Camera& c = state_.camera;
  const sim::Trajectory& tr = state_.trajectory;
  const bool past_computed = tr.empty() || state_.play_time > tr.t_end();
  const ViewportKey key{view_.get(),
                        w,
                        h,
                        state_.generation,
                        past_computed ? static_cast<long>(tr.samples.size()) : -1L,
                        state_.modes.shown >= 0 ? state_.modes.clock : state_.play_time,
                        state_.modes.shown,
                        {c.target.x(), c.target.y(), c.target.z(), c.azimuth_deg, c.elevation_deg, c.distance,
                         c.fov_deg, c.orthographic ? 1.0f : 0.0f, static_cast<float>(state_.camera_frame)},
                        state_.show_loads ? state_.load_scale : 0.0f,
                        state_.exaggeration};
  if (key == viewport_key_ && viewport_drawn_) return;
  viewport_key_ = key;
  viewport_drawn_ = true;
  std::vector<sim::Pose> poses;
  current_poses(poses);
  const std::vector<render::LoadArrow> arrows = current_load_arrows(poses, state_.load_legend);
  state_.load_arrows_drawn = static_cast<int>(arrows.size());
  std::vector<double> q;
  current_coordinates(q);
  view_->deform(state_.scene.model, q.data(), state_.exaggeration);
  viewport_->bind();
  view_->draw(poses, state_.camera, w, h, arrows);
  viewport_->resolve();
}

void GuiApp::draw_plots_texture() {
  // Plots are the costliest thing to draw in software GL: redraw them only
  // when their data or size changed, at most twice a second while a
  // run streams in. The play-head is drawn over them by the panel.
  const int w = std::max(16, state_.plots_width), h = std::max(16, state_.plots_height);
  // The summary (the torque margins) arrives after the last sample, which
  // is drawn at once: the throttle is for a run streaming in.
  const PlotsKey key{state_.generation, state_.trajectory.samples.size(), state_.ghost.samples.size(), w, h,
                     state_.plot_tab,   state_.plots_version, state_.progress.summary != nullptr};
  const double now = now_seconds();
  if (plots_ && key == plots_key_) return;
  if (plots_ && !state_.run_integrated() && now - plots_drawn_at_ < 0.5) return;
  if (!plots_ || plots_->width() != w || plots_->height() != h) plots_ = std::make_unique<render::Framebuffer>(w, h, 1);
  if (!plots_layer_) plots_layer_ = std::make_unique<render::ImGuiLayer>(std::round(15 * state_.applied_scale));
  plots_key_ = key;
  plots_drawn_at_ = now;
  plot_frames_.clear();
  plots_->bind();
  const ImVec4 background = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  render::clear_bound_framebuffer(background.x, background.y, background.z);
  plots_layer_->begin_frame(w, h);
  const std::vector<render::PlotKind> kinds = shown_plots(state_);
  const render::PlotChoice choice = plot_choice(state_);
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const ImVec4 cell = plot_cell(k, kinds.size(), ImVec2(static_cast<float>(w), static_cast<float>(h)));
    if (state_.trajectory.empty()) continue;
    const render::PlotSpec spec = render::trajectory_plot(kinds[k], state_.scene, state_.trajectory, choice);
    plot_frames_.push_back(
        render::draw_plot(plots_layer_->draw_list(), ImVec2(cell.x, cell.y), ImVec2(cell.z, cell.w), spec, false));
  }
  plots_layer_->end_frame();
  plots_->resolve();
  if (state_.run_integrated() && state_.edited_at > state_.curves_at) state_.curves_at = now_seconds();
}

}  // namespace unfurl::app
