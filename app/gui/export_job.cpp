#include "export_job.hpp"

#include <chrono>
#include <cstdio>

#include "unfurl/io/output_file.hpp"
#include "unfurl/io/png_file.hpp"

namespace unfurl::app {

ExportJob::ExportJob(const ExportRequest& request, const sim::Scene& scene, const sim::SceneVisuals& visuals,
                     const sim::Trajectory& trajectory, const render::Camera& camera,
                     std::optional<render::LoadArrowScale> loads)
    : request_(request),
      scene_(scene),
      trajectory_(trajectory),
      camera_(camera),
      loads_(loads),
      times_(frame_times(request.options, trajectory.t_begin(), trajectory.t_end())),
      renderer_(std::make_unique<render::FrameRenderer>(scene_, visuals, request.options.width, request.options.height,
                                                        mesh_directories(scene_))) {
  if (request_.frames) io::make_directory(request_.dir);
  if (request_.options.video)
    video_ = std::make_unique<io::VideoPipe>(*request_.options.video, request_.options.width, request_.options.height,
                                             request_.options.fps);
  encoder_ = std::thread([this] { encode(); });
}

ExportJob::~ExportJob() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_drawing_ = true;
  }
  ready_.notify_all();
  encoder_.join();
}

void ExportJob::cancel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
    finished_drawing_ = true;
    queue_.clear();
  }
  ready_.notify_all();
}

bool ExportJob::step(double budget_ms) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> q;
  std::vector<sim::Pose> poses;
  while (drawn_ < times_.size()) {
    {
      // Do not run ahead of the encoder by more than a few frames.
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_.empty() || cancelled_) break;
      if (queue_.size() >= 4) return true;
    }
    trajectory_.coordinates_at(times_[drawn_], q);
    render::poses_in_camera_frame(request_.options.camera_frame, scene_.model, q.data(), poses);
    renderer_->deform(scene_.model, q.data(), request_.options.exaggerate);
    render::Image image;
    std::vector<render::LoadArrow> arrows;
    if (loads_) arrows = render::load_arrows(scene_, trajectory_, trajectory_.sample_at(times_[drawn_]), poses, *loads_);
    renderer_->frame(poses, render::time_caption(times_[drawn_]), camera_, image, arrows,
                     loads_ ? render::load_arrow_legend(*loads_) : "");
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.emplace_back(drawn_, std::move(image));
    }
    ready_.notify_all();
    ++drawn_;
    if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() > budget_ms)
      return true;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  finished_drawing_ = true;
  ready_.notify_all();
  return !encoder_done_;
}

void ExportJob::encode() {
  for (;;) {
    std::pair<std::size_t, render::Image> item;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return !queue_.empty() || finished_drawing_; });
      if (queue_.empty()) break;
      item = std::move(queue_.front());
      queue_.pop_front();
    }
    try {
      if (request_.frames) {
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%05zu.png", item.first);
        io::write_png(item.second, request_.dir + name);
      }
      if (video_) video_->add(item.second);
      std::lock_guard<std::mutex> lock(mutex_);
      ++encoded_;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = e.what();
      queue_.clear();
      break;
    }
    ready_.notify_all();
  }
  std::string error;
  bool cancelled = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancelled = cancelled_;
  }
  if (cancelled) video_.reset();  // abandons the unfinished video
  if (video_) {
    try {
      if (error_.empty()) video_->finish();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (error_.empty()) error_ = error;
  encoder_done_ = true;
}

std::string ExportJob::result() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!error_.empty()) return "export failed: " + error_;
  if (cancelled_)
    return "export cancelled after " + std::to_string(encoded_) + " of " + std::to_string(times_.size()) + " frames" +
           (request_.frames && encoded_ > 0 ? " (those frames are in " + request_.dir + ")" : "") +
           (request_.options.video ? "; no video written" : "");
  std::string what = std::to_string(times_.size()) + " frames";
  if (request_.frames) what += " in " + request_.dir;
  if (request_.options.video) what += ", video " + *request_.options.video;
  if (video_ && !video_->note().empty()) what += " (" + video_->note() + ")";
  return "exported " + what;
}

}  // namespace unfurl::app
