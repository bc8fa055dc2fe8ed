// The exact motion of a compound pendulum: one body on one revolute joint to
// a fixed base, under uniform gravity and nothing else, released at rest.
// With phi = q - q_eq (q_eq: centre of mass straight "down" along gravity
// across the axis) and omega^2 = m g_perp d / I_axis,
//   phi'' = -omega^2 sin phi,   sin(phi / 2) = k sn(K(k) - omega t | k),
// k = sin(phi0 / 2): the reference the work-precision report measures
// errors against when a scene has it.
#pragma once

#include <optional>

#include "unfurl/sim/scene.hpp"

namespace unfurl::studies {

// Jacobi's sn(u | m), m = k^2 in [0, 1), by the arithmetic-geometric mean.
double jacobi_sn(double u, double m);

struct ExactPendulum {
  double q_eq = 0;   // the stable equilibrium
  double omega = 0;  // small-amplitude angular frequency
  double phi0 = 0;   // release angle from q_eq
  double angle(double t) const;  // q(t)
};

// The exact solution, if the scene is such a pendulum; nullopt otherwise.
std::optional<ExactPendulum> exact_pendulum(const sim::Scene& scene);

}  // namespace unfurl::studies
