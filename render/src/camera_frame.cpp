#include "unfurl/render/camera_frame.hpp"

namespace unfurl::render {

std::optional<CameraFrame> parse_camera_frame(const std::string& name) {
  if (name == "inertial") return CameraFrame::inertial;
  if (name == "bus") return CameraFrame::bus;
  return std::nullopt;
}

const char* camera_frame_name(CameraFrame frame) { return frame == CameraFrame::bus ? "bus" : "inertial"; }

void poses_in_camera_frame(CameraFrame frame, const sim::Model& model, const double* q, std::vector<sim::Pose>& poses) {
  sim::body_poses(model, q, poses);
  if (frame != CameraFrame::bus || !model.free_floating()) return;
  const sim::Pose bus = poses[0];
  for (sim::Pose& p : poses) {
    p.position = bus.rotation * (p.position - bus.position);
    p.rotation = p.rotation * bus.rotation.transpose();
  }
}

}  // namespace unfurl::render
