#include "unfurl/render/camera.hpp"

#include <cmath>

namespace unfurl::render {

namespace {
constexpr float kDegree = static_cast<float>(M_PI / 180);
}

Eigen::Vector3f Camera::eye() const {
  const float az = azimuth_deg * kDegree, el = elevation_deg * kDegree;
  return target + distance * Eigen::Vector3f(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
}

Eigen::Matrix4f Camera::view() const {
  const Eigen::Vector3f e = eye();
  const Eigen::Vector3f forward = (target - e).normalized();
  // Straight up or down, z is no longer a usable up direction.
  const Eigen::Vector3f up_hint = std::abs(forward.z()) > 0.999f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f right = forward.cross(up_hint).normalized();
  const Eigen::Vector3f up = right.cross(forward);
  Eigen::Matrix4f V = Eigen::Matrix4f::Identity();
  V.block<1, 3>(0, 0) = right.transpose();
  V.block<1, 3>(1, 0) = up.transpose();
  V.block<1, 3>(2, 0) = -forward.transpose();
  V(0, 3) = -right.dot(e);
  V(1, 3) = -up.dot(e);
  V(2, 3) = forward.dot(e);
  return V;
}

Eigen::Matrix4f Camera::projection(float aspect) const {
  const float near = 0.01f * distance, far = 20.0f * distance;
  const float f = 1.0f / std::tan(0.5f * fov_deg * kDegree);
  Eigen::Matrix4f P = Eigen::Matrix4f::Zero();
  if (orthographic) {
    // The frustum's cross-section at the target: zooming (distance) still
    // scales the picture.
    const float half_h = distance / f;
    P(0, 0) = 1 / (half_h * aspect);
    P(1, 1) = 1 / half_h;
    P(2, 2) = -2 / (far - near);
    P(2, 3) = -(far + near) / (far - near);
    P(3, 3) = 1;
    return P;
  }
  P(0, 0) = f / aspect;
  P(1, 1) = f;
  P(2, 2) = (far + near) / (near - far);
  P(2, 3) = 2 * far * near / (near - far);
  P(3, 2) = -1;
  return P;
}

void Camera::fit(const Eigen::AlignedBox3f& bounds, float aspect) {
  // Centre the box's projection and pull back until all its corners are
  // inside the picture, with a small margin.
  target = bounds.center();
  const float radius = std::max(0.5f * bounds.diagonal().norm(), 1e-3f);
  auto extent = [&](float d, Eigen::Vector2f& centre) {
    distance = d;
    const Eigen::Matrix4f P = projection(aspect) * view();
    Eigen::Vector2f lo(1e9f, 1e9f), hi(-1e9f, -1e9f);
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector4f c = P * bounds.corner(static_cast<Eigen::AlignedBox3f::CornerType>(k)).homogeneous();
      if (c.w() <= 0) return 1e9f;
      const Eigen::Vector2f ndc = c.head<2>() / c.w();
      lo = lo.cwiseMin(ndc), hi = hi.cwiseMax(ndc);
    }
    centre = 0.5f * (lo + hi);
    return std::max(hi.x() - lo.x(), hi.y() - lo.y()) / 2;
  };
  Eigen::Vector2f centre;
  for (int pass = 0; pass < 3; ++pass) {
    float near = 0.5f * radius, far = 50 * radius;
    for (int it = 0; it < 40; ++it) {
      const float mid = 0.5f * (near + far);
      (extent(mid, centre) > 0.9f ? near : far) = mid;
    }
    extent(far, centre);
    // Shift the target along the view's right and up so the box is centred.
    const Eigen::Matrix4f V = view();
    const float half_h = distance * std::tan(0.5f * fov_deg * kDegree), half_w = half_h * aspect;
    target += centre.x() * half_w * V.block<1, 3>(0, 0).transpose() + centre.y() * half_h * V.block<1, 3>(1, 0).transpose();
  }
}

const std::vector<std::string>& camera_preset_names() {
  static const std::vector<std::string> names{"iso", "side", "top", "end", "bottom"};
  return names;
}

std::optional<Camera> camera_preset(const std::string& name, const Eigen::AlignedBox3f& bounds, float aspect) {
  Camera c;
  if (name == "iso") {
    c.azimuth_deg = -40, c.elevation_deg = 30;
  } else if (name == "side") {
    c.azimuth_deg = 0, c.elevation_deg = 0;
  } else if (name == "top") {
    c.azimuth_deg = -90, c.elevation_deg = 89.9f;
  } else if (name == "end") {
    c.azimuth_deg = 90, c.elevation_deg = 15;
  } else if (name == "bottom") {
    c.azimuth_deg = -90, c.elevation_deg = -89.9f;
  } else {
    return std::nullopt;
  }
  c.fit(bounds, aspect);
  return c;
}

}  // namespace unfurl::render
