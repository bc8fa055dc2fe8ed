#include "unfurl/sim/elements/joint_driver.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/elements/latch.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

const char* driver_profile_name(JointDriver::Profile profile) {
  return profile == JointDriver::Profile::move ? "move" : "spin_up";
}

std::optional<JointDriver::Profile> parse_driver_profile(const std::string& name) {
  if (name == "move") return JointDriver::Profile::move;
  if (name == "spin_up") return JointDriver::Profile::spin_up;
  return std::nullopt;
}

JointDriver::Motion JointDriver::at(double t) const {
  const double T = duration, tau = std::clamp(t - start, 0.0, T), s = tau / T;
  const double two_pi = 2 * M_PI;
  // c(s) = s - sin(2 pi s) / (2 pi), c' = 1 - cos(2 pi s) per unit s.
  const double c = s - std::sin(two_pi * s) / two_pi;
  const bool moving = t - start >= 0 && t - start <= T;
  const double c_rate = moving ? (1 - std::cos(two_pi * s)) / T : 0.0;
  const double c_acceleration = moving ? two_pi * std::sin(two_pi * s) / (T * T) : 0.0;
  if (profile == Profile::move) return {amount * c, amount * c_rate, amount * c_acceleration};
  // The rate is amount c(s); its integral over [0, s] is T (s^2 / 2 +
  // (cos(2 pi s) - 1) / (2 pi)^2), and the rate holds after the ramp.
  const double ramp = T * (s * s / 2 + (std::cos(two_pi * s) - 1) / (two_pi * two_pi));
  const double after = std::max(0.0, t - start - T);
  return {amount * (ramp + after), amount * c, amount * c_rate};
}

std::shared_ptr<ForceElement> JointDriver::scaled(double L, double, const Model& model) const {
  auto d = std::make_shared<JointDriver>(*this);
  d->amount *= angle_scale(model, L);
  return d;
}

std::vector<LoadColumn> JointDriver::load_columns(const Model& model) const { return {column(model, "drive_torque")}; }

void JointDriver::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  const Joint& j = scene.model.joints[joint];
  if (j.compliant)
    throw SceneInvalid(field + ".joint", "joint '" + j.name + "' is compliant: a driver holds a rigid joint");
  if (!std::isfinite(amount)) throw SceneInvalid(field + ".amount", "must be a finite number");
  check_positive(duration, field + ".duration");
  check_non_negative(start, field + ".start");
  int drivers = 0;
  for (const auto* d : scene.elements_of<JointDriver>()) drivers += d->joint == joint;
  if (drivers > 1) throw SceneInvalid(field + ".joint", "joint '" + j.name + "' has more than one driver");
  for (const Latch* latch : scene.latches())
    if (latch->joint == joint)
      throw SceneInvalid(field + ".joint",
                         "joint '" + j.name + "' has a latch: a driven joint's motion is the driver's");
}

std::vector<ElementParameter> JointDriver::parameters(const Model& model) const {
  const bool move = profile == Profile::move;
  const std::string unit = angle_unit(model, joint);
  return {{"amount", move ? "move by [" + unit + "]" : "final rate [" + unit + "/s]", amount, 0.01, 0, 0,
           move ? "how far the driver moves the joint from its initial position"
                : "the rate the driver spins the joint up to"},
          {"duration", "duration [s]", duration, 0.1, 1e-6, 1e9,
           move ? "how long the move takes (cycloidal: at rest at both ends)" : "how long the rate takes to rise"},
          {"start", "start [s]", start, 0.1, 0, 1e9, "when the driver starts"}};
}

std::string JointDriver::note() const { return std::string("profile: ") + driver_profile_name(profile); }

}  // namespace unfurl::sim
