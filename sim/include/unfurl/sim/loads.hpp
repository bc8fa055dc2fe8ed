// The loads an engineer sizes hardware with, at one instant: per joint the
// generalized force of each element (spring, damper, friction, latch) and the wrench
// the parent transmits to the child through the joint; per loop component
// the regulator's constraint force.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/spatial.hpp"

namespace unfurl {

struct JointLoad {
  double spring = 0;  // -k (q - q_free), N m (or N for a slider)
  double damper = 0;  // -c dq: the springs' damping and the dampers
  double latch = 0;   // -k_L (q - q_L) - c_L dq once engaged
  double friction = 0;  // -T_c tanh(dq / v_s) - c_v dq (friction.hpp)
  // The wrench from the parent on the child: force (N) and moment (N m)
  // about the hinge point, in the child body's frame. Its component along
  // the joint's motion axis is the sum of the element forces above.
  Vec6 reaction = Vec6::Zero();
};

struct Loads {
  std::vector<JointLoad> joints;   // per joint (every joint, fixed ones too)
  // Per active loop component: the force on the split body from its image
  // (its negative acts on the image), at the body's origin, in its frame.
  std::vector<double> loop_force;
  // Per point spring (scene order): its tension, N (> 0 pulls).
  std::vector<double> point_spring_tension;
};

// The largest magnitude a quantity took and when.
struct Peak {
  double value = 0;
  double t = std::numeric_limits<double>::quiet_NaN();
  void update(double x, double at) {
    if (x > value || std::isnan(t)) value = x, t = at;
  }
};

// Peaks over every step the integrator took (not only the samples: a latch's
// shock lasts milliseconds), and the largest geometric loop gap.
struct RunPeaks {
  std::vector<Peak> latch_torque;   // per latch, |tau_L|
  std::vector<Peak> hinge_force;    // per joint, |f| of the reaction
  std::vector<Peak> hinge_moment;   // per joint, |m| about the hinge point
  Peak gap_m, gap_rad;              // over all loops
  Peak gap_m_before_latch, gap_rad_before_latch;
};

// The name of loop component axis a: fx, fy, fz, mx, my, mz.
const char* wrench_component_name(int axis);

}  // namespace unfurl
