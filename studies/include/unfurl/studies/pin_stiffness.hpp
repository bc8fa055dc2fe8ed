// How the compliant pantograph's loads follow the stiffness of its
// cross-link pins: the peak hinge and pin forces of the nominal deployment
// and of an off-nominal one (one root spring 2 % stiffer, the asymmetric
// latch-up where the rigid model's loads are indeterminate) as the
// bushings' translational stiffness goes from soft to nearly rigid, beside
// the rigid pantograph's figures for the same two deployments.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"

namespace unfurl::studies {

// The two deployments: as built, and with j1's spring 2 % stiffer.
struct PinStiffnessDeployment {
  std::string label;  // "nominal", "off-nominal (j1 spring +2 %)"
  std::vector<std::pair<std::string, std::string>> overrides;
};
std::vector<PinStiffnessDeployment> pin_stiffness_deployments();

// What one run gives.
struct PinLoads {
  sim::RunStatus status = sim::RunStatus::finished;
  std::string failure;
  double deployment_time = 0;           // the last latch, s (0 if not all latched)
  double peak_hinge_force = 0;          // the largest over the joints, N (determinate steps)
  std::string peak_hinge_joint;
  double peak_pin_force = 0;            // the largest over the bushings, N (compliant runs)
  std::optional<bool> loads_determinate;
  double peak_hinge_force_indeterminate = 0;  // rigid runs: the indeterminate peak (RunPeaks)
  long steps = 0;
  double wall_time_s = 0;
};

struct PinStiffnessCase {
  int deployment = 0;  // index into pin_stiffness_deployments()
  double stiffness = 0;  // N/m along all three axes of every pin; 0 for the rigid pantograph
  PinLoads loads;
};

// The compliant pantograph with every pin's translational stiffness k
// (its damping and rotational values as built), at rtol for t_end seconds.
PinStiffnessCase run_compliant_pins(int deployment, double k, double rtol, double t_end);
// The rigid pantograph (split bodies and the regulator).
PinStiffnessCase run_rigid_pins(int deployment, double rtol, double t_end);

}  // namespace unfurl::studies
