// The deployment torque margin of every driven joint (a hinge with a spring
// and a latch), as mechanism reviews ask for it: the driving torque against
// the resistive torques, each multiplied by its uncertainty factor, along
// the joint's travel. The motorization factor is
//   MoF = T_drive / (f_S T_spring + f_F T_friction + f_D T_damping + f_H T_harness + f_I T_inertia)
// after ECSS-E-ST-33-01C's motorization factor (clause 4.7.5, "Motorization
// factor"; its uncertainty factors, Table 4-2 as this project reads it:
// 1.2 on springs, 3 on friction, damping, hysteresis and harness, 1.1 on
// inertia; required MoF 2) and NASA-STD-5017's torque margin, TM = MoF - 1
// (required 1). The defaults are those figures; a project sets its own
// (TorqueMarginFactors) and should check them against its copy of the
// standard, which this code was not written from (scene files set them
// under `torque_margin:`).
//
// - T_drive: the joint's springs that push it towards its latch (their
//   elastic torque).
// - T_spring: its springs that hold it back.
// - T_friction: its friction (Coulomb, and viscous at the run's rate).
// - T_damping: its springs' and dampers' viscous torque at the run's rate.
// - T_harness: everything else that holds it back: cables and point
//   springs, bushings, applied forces and gravity, as the generalized force
//   they put on the joint (the harness and cable drag of a real array).
// - T_inertia: the torque to give the joint's articulated inertia a
//   required acceleration (TorqueMarginFactors::required_acceleration, 0
//   by default: a spring-driven deployment has none; the acceleration the
//   run has is what the spare torque gives, not a resistance).
// Torques that help the motion other than the driving springs are not
// counted as drive.
//
// Two evaluations: along the run (every sample before the joint latches,
// the rates as they were), and quasi-static over the whole travel (from
// where the joint starts to its latch, at rest, the other joints where the
// run had them when this one passed that angle; where the run never got
// there, as the run left them).
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/torque_margin_result.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::sim {

// The driven joints: those with a spring and a latch, each once, in the
// latches' order.
std::vector<int> driven_joints(const Scene& scene);

// The driven joints' margins (joints with a spring and a latch), from a run
// of the scene, weighed by the scene's factors (Scene::torque_margin).
// Where *cancel becomes true it stops, its result incomplete: for a caller
// that then discards it (the workbench, whose edit started another run).
std::vector<JointTorqueMargin> torque_margins(const Scene& scene, const Trajectory& run,
                                              const std::atomic<bool>* cancel = nullptr);

}  // namespace unfurl::sim
