// The uncertainty factors and the required motorization factor of the
// torque margin (torque_margin.hpp), a scene's `torque_margin:` settings.
#pragma once

namespace unfurl::sim {

struct TorqueMarginFactors {
  double spring = 1.2, friction = 3.0, damping = 3.0, harness = 3.0, inertia = 1.1;
  double required = 2.0;               // the motorization factor a joint must reach
  double required_acceleration = 0.0;  // rad/s^2 (m/s^2 on a slider)
};

}  // namespace unfurl::sim
