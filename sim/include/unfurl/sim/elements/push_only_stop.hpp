// The law of a stop that pushes and never pulls, shared by a joint's limits
// and a latch's free play: tau = -k x - c q' where the joint is x past the
// stop, and 0 where that torque would pull the joint back onto it (a
// damper cannot hold a joint against a stop it is leaving).
#pragma once

namespace unfurl::sim {

inline double push_only_torque(double x, double q_dot, double k, double c) {
  if (x == 0) return 0.0;
  const double tau = -k * x - c * q_dot;
  return tau * x > 0 ? 0.0 : tau;
}

}  // namespace unfurl::sim
