#include <cmath>

#include "unfurl/sim/loop.hpp"

namespace unfurl::sim {

ClosureError closure_error(const Pose& body, const Pose& image) {
  const Eigen::AngleAxisd relative(image.rotation * body.rotation.transpose());
  return {(body.position - image.position).norm(), std::abs(relative.angle())};
}

Vec6 closure_mismatch(const Pose& body, const Pose& image) {
  Vec6 g;
  g.head<3>() = body.rotation * (body.position - image.position);
  // G_image G_body^T turns body coordinates into image coordinates; its
  // rate at identity is (w_body - w_image)~. Eigen takes the log through
  // the quaternion (2 atan2(|v|, w) v / |v|), smooth through zero.
  const Eigen::AngleAxisd relative(Eigen::Quaterniond(image.rotation * body.rotation.transpose()));
  g.tail<3>() = relative.angle() * relative.axis();
  return g;
}

}  // namespace unfurl::sim
