// An orbit camera around a target in the base frame (z up): azimuth from +x
// towards +y, elevation above the x-y plane, distance from the target.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace unfurl::render {

struct Camera {
  Eigen::Vector3f target = Eigen::Vector3f::Zero();
  float azimuth_deg = -40;
  float elevation_deg = 30;
  float distance = 6;
  float fov_deg = 35;  // vertical
  // Orthographic: parallel projection (a true view along an axis, lengths
  // comparable across the picture), as wide as the perspective view is at
  // the target.
  bool orthographic = false;

  Eigen::Vector3f eye() const;
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;
  // Moves the target and distance so a sphere around `bounds` fills the view.
  void fit(const Eigen::AlignedBox3f& bounds, float aspect);
};

// Named views: iso (default), side (from +x, along the hinge axes of the
// built-in arrays: the folding plane), top (from +z: the panels' cells), end
// (from +y, back towards the bus), bottom (from -z).
const std::vector<std::string>& camera_preset_names();
// The preset's direction, fitted to `bounds`; nullopt for an unknown name.
std::optional<Camera> camera_preset(const std::string& name, const Eigen::AlignedBox3f& bounds, float aspect);

}  // namespace unfurl::render
