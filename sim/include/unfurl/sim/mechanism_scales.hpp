// The mechanism's own sizes, taken from its scene: what makes every
// tolerance, gain and regularization of the solver dimensionless, so that a
// mechanism scaled by lengths x L and masses x M (time unchanged) runs the
// same steps to the same angles (studies/scene_scaling.hpp).
#pragma once

#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

struct MechanismScales {
  // m: the bodies' mass-weighted radius of gyration about their joints,
  // sqrt(sum (tr J_c / 2 + m |c - r_joint|^2) / sum m). A loop's linear gap
  // and force are measured against it (the closure's metric).
  double length = 1;
  // rad/s: the fastest rate the mechanism has of its own: the highest
  // frequency of a joint's stiffness (latches counted engaged) against its
  // articulated inertia, the pendulum frequency of gravity over `length`,
  // the initial rates and the drivers' peak rates.
  double rate = 1;
  // Per velocity coordinate: its articulated inertia at q0 (kg m^2, or kg
  // on a slider).
  std::vector<double> inertia;

  // What a distance counts as, against an angle: distance / length.
  double relative_length(double metres) const { return metres / length; }
};

// The scales at the scene's initial state (sweep: scratch).
MechanismScales mechanism_scales(const Scene& scene, Sweep& sweep);
// The length alone (from the bodies).
double mechanism_length(const Model& model);

}  // namespace unfurl::sim
