// Exporting a time range as PNG frames and/or a video from the GUI, through
// the same renderer and encoders as `unfurl render`. Frames are drawn on the
// UI thread (they need its GL context) a few per UI frame; encoding them
// (PNG, ffmpeg) runs on a thread of its own, so the UI stays responsive.
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/load_arrows.hpp"
#include "gui_state.hpp"
#include "unfurl/io/video_pipe.hpp"

namespace unfurl::app {

class ExportJob {
 public:
  // Throws std::runtime_error when the renderer, directory or ffmpeg fail.
  // With `loads`, the frames show the load arrows at that scale.
  ExportJob(const ExportRequest& request, const sim::Scene& scene, const sim::SceneVisuals& visuals,
            const sim::Trajectory& trajectory, const render::Camera& camera,
            std::optional<render::LoadArrowScale> loads = std::nullopt);
  ~ExportJob();  // stops the encoder
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;

  // Draws frames for about `budget_ms` milliseconds; returns false when all
  // frames are drawn and encoded (or encoding failed).
  bool step(double budget_ms);
  std::size_t done() const { return drawn_; }
  std::size_t total() const { return times_.size(); }
  // Stops at the frame being encoded: the frames written stay (each one
  // complete), an unfinished video is removed.
  void cancel();
  // What happened: the files written, or the error.
  std::string result();

 private:
  void encode();

  ExportRequest request_;
  const sim::Scene scene_;
  const sim::Trajectory trajectory_;
  render::Camera camera_;
  std::optional<render::LoadArrowScale> loads_;
  std::vector<double> times_;
  std::unique_ptr<render::FrameRenderer> renderer_;
  std::size_t drawn_ = 0;

  // The encoder thread's queue.
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::pair<std::size_t, render::Image>> queue_;
  bool finished_drawing_ = false, encoder_done_ = false, cancelled_ = false;
  std::size_t encoded_ = 0;
  std::string error_;
  std::unique_ptr<io::VideoPipe> video_;
  std::thread encoder_;
};

}  // namespace unfurl::app
