// A model exported by `unfurl export mjcf` run by MuJoCo from its keyframe
// 'initial' with RK4 at a fixed step. The latches the model keeps as custom
// numeric data (latch:JOINT = position, stiffness, damping, side) engage
// where a step crosses them (the step is cut there) and act through
// mjcb_passive. Shared by the peer tests' runner and the side-by-side
// benchmark; one run at a time per process (MuJoCo's callback is global).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace unfurl::peer {

struct MujocoRun {
  std::vector<std::string> joints;          // qpos entries named as unfurl's q (Model::position_name)
  std::vector<double> t;                    // sample times: 0, SAMPLE, 2 SAMPLE, ...
  std::vector<std::vector<double>> q;       // per sample, per qpos entry
  std::vector<double> energy;               // per sample: kinetic + potential + latches
  std::vector<std::pair<double, std::string>> latches;  // engagement time, joint
  int warnings = 0;                         // MuJoCo's warnings while it ran
  long steps = 0;                           // mj_step calls (latch cuts included)
  double wall_s = 0;                        // the stepping loop's wall time (not loading)
};

// Throws std::runtime_error when the model does not load (or loads with a
// warning).
MujocoRun run_mujoco(const std::string& xml_path, double t_end, double dt, double sample);

}  // namespace unfurl::peer
