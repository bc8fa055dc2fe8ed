// Loads drawn on the 3D view: at each joint's hinge point the force the
// parent applies to the child (an arrow along it), and at each engaged
// latch its torque on the joint (a double-headed arrow along the hinge
// axis, by the right-hand rule). An arrow's length is fixed per run
// (LoadArrowScale), so scrubbing the timeline shows a load grow and fall;
// where rigid mechanics does not determine the hinge forces
// (Loads::determinacy) the minimum-norm ones are drawn grey.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::render {

struct LoadArrow {
  enum class Kind { force, torque, indeterminate_force };
  Kind kind = Kind::force;
  Eigen::Vector3f from = Eigen::Vector3f::Zero();    // where it acts, in the frame of the poses
  Eigen::Vector3f vector = Eigen::Vector3f::Zero();  // drawn length and direction, metres
  float radius = 0;                                  // the shaft's, metres
};

// The run's largest hinge force and largest latch torque, each drawn
// `reach` long: a fraction of the scene's size times the user's factor.
struct LoadArrowScale {
  double peak_force = 0;   // N
  double peak_torque = 0;  // N m (N for a prismatic joint's latch)
  float reach = 0;         // metres
  float thickness = 0;     // a shaft's radius, metres
};

// `scene_size`: the diagonal of what the view draws. `factor` lengthens
// (> 1) or shortens every arrow.
LoadArrowScale load_arrow_scale(const sim::Scene& scene, const sim::Trajectory& trajectory, float scene_size,
                                float factor = 1);

// The arrows of one sample of the run, placed by `poses` (the sample's, in
// any frame: what the view draws).
std::vector<LoadArrow> load_arrows(const sim::Scene& scene, const sim::Trajectory& trajectory,
                                   const sim::Sample& sample, const std::vector<sim::Pose>& poses,
                                   const LoadArrowScale& scale);

// "loads: hinge force 163 N, latch torque 35.2 N m at full length".
std::string load_arrow_legend(const LoadArrowScale& scale);

}  // namespace unfurl::render
