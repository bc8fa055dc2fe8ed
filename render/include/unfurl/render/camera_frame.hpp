// The frame the camera rides in. A fixed base's frame is the inertial one;
// with a free-floating bus (body 0 on a free joint) the camera can ride with
// the bus, so the array is seen deploying from the spacecraft, or stay in
// the inertial frame, where the bus is seen to turn and drift in reaction.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/kinematics.hpp"

namespace unfurl::render {

enum class CameraFrame { inertial, bus };

std::optional<CameraFrame> parse_camera_frame(const std::string& name);
const char* camera_frame_name(CameraFrame frame);

// The bodies' poses at q, seen from `frame` (the bus frame only for a
// free-floating model; otherwise the base frame).
void poses_in_camera_frame(CameraFrame frame, const sim::Model& model, const double* q, std::vector<sim::Pose>& poses);

}  // namespace unfurl::render
