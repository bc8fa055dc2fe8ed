// Hinge friction: Coulomb plus viscous, with the Coulomb part smoothed near
// zero speed so the right-hand side stays smooth and the integrators keep
// their order.
#pragma once

#include <cmath>

namespace unfurl {

// tau_f = -coulomb tanh(dq / velocity_scale) - viscous dq on one joint.
// Within |dq| < velocity_scale the Coulomb torque ramps through zero (its
// slope there is coulomb / velocity_scale): a stuck joint creeps at about
// velocity_scale * (applied torque / coulomb) instead of sticking, which is
// the price of a smooth law. Choose velocity_scale well below the speeds
// that matter (the default, 1e-3 rad/s, is 0.06 deg/s).
struct JointFriction {
  int joint = 0;
  double coulomb = 0;            // N m (N for a slider): the sliding friction torque
  double viscous = 0;            // N m s/rad
  double velocity_scale = 1e-3;  // rad/s (m/s)

  double torque(double dq) const { return -coulomb * std::tanh(dq / velocity_scale) - viscous * dq; }
  // The power it takes out of the mechanism, -tau_f dq >= 0.
  double dissipation(double dq) const { return -torque(dq) * dq; }
};

}  // namespace unfurl
