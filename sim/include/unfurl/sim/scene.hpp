// A scene: the mechanism (tree, forces, latches, loops, regulator), its
// initial state and how to run it. What the renderer draws is apart
// (visuals.hpp).
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/forces.hpp"
#include "unfurl/sim/friction.hpp"
#include "unfurl/sim/latch.hpp"
#include "unfurl/sim/loop.hpp"
#include "unfurl/sim/model.hpp"
#include "unfurl/sim/point_spring.hpp"
#include "unfurl/sim/regulator_settings.hpp"
#include "unfurl/sim/run_settings.hpp"

namespace unfurl {

struct Scene {
  std::string name;
  std::string description;
  std::string source;  // the file it came from, or "built-in"
  Model model;
  std::vector<JointSpring> springs;  // the file's springs, then its dampers
  std::size_t dampers_from = 0;      // springs[dampers_from..] came from `dampers:`
  std::vector<JointFriction> friction;
  std::vector<PointSpring> point_springs;
  std::vector<BodyLoad> loads;
  std::vector<Latch> latches;
  std::vector<Loop> loops;
  RegulatorSettings regulator;
  std::vector<double> q0;     // per position coordinate
  std::vector<double> dq0;    // per velocity coordinate (used when p0 is empty)
  std::vector<double> p0;     // per velocity coordinate, optional
  double closure_tolerance = 1e-6;  // how far the initial loops may be open
  RunSettings run;
};

}  // namespace unfurl
