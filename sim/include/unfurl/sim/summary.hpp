// The figures a user reads off a run: latch times, the largest geometric
// loop gap, the peak loads, energy at both ends, the final state. Gaps and
// loads are over every step the integrator took (RunPeaks), not only the
// samples.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/clearance_result.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/torque_margin.hpp"

namespace unfurl::sim {

struct RunSummary {
  std::vector<std::pair<std::string, double>> latch_times;  // joint name, time
  std::vector<std::string> unlatched;                       // joints whose latch never engaged
  double max_closure_gap = 0;                               // the largest gap over loops and steps
  double max_closure_angle = 0;
  double max_closure_gap_before_latch = 0;  // the same up to the first latch
  double max_closure_angle_before_latch = 0;
  struct NamedPeak {
    std::string joint;
    Peak peak;
  };
  std::vector<NamedPeak> peak_latch_torque;  // per latch
  std::vector<NamedPeak> peak_hinge_force;   // per joint
  std::vector<NamedPeak> peak_hinge_moment;  // per joint
  // The elements' own peaks (a bushing's force and moment), by quantity
  // and the element's handle.
  struct ElementPeakValue {
    std::string quantity, name, unit;
    Peak peak;
  };
  std::vector<ElementPeakValue> element_peaks;
  // The sensors' (peak_acceleration, ...), by sensor name.
  std::vector<ElementPeakValue> sensor_peaks;
  // Whether the motion determined every load (nullopt: not assessed, a
  // scene with more loop components than the analysis takes); where it did
  // not, from when to when, and the peaks there (RunPeaks: the minimum-norm
  // reactions, and the rigid ones running into and out of the spans).
  std::optional<bool> loads_determinate;
  std::vector<std::array<double, 2>> indeterminate_spans;
  std::vector<NamedPeak> peak_hinge_force_indeterminate;
  std::vector<NamedPeak> peak_hinge_moment_indeterminate;
  // The driven joints' torque margins (torque_margin.hpp), with the
  // factors they were weighed by.
  std::vector<JointTorqueMargin> torque_margins;
  TorqueMarginFactors torque_margin_factors;
  // An interrupt stopped the summary (summarize's cancel): its torque
  // margins and clearance are missing, not partial.
  bool interrupted = false;
  // The smallest motorization factor over the driven joints (infinite
  // without any), and whether every one reaches the required factor.
  double worst_motorization_factor() const;
  bool torque_margins_pass() const { return worst_motorization_factor() >= torque_margin_factors.required; }
  // The bodies' clearance (clearance_result.hpp; nullopt: not checked, as
  // summarize() alone leaves it: the solids come from the scene's visuals,
  // which the solver does not read).
  std::optional<Clearance> clearance;
  double energy_initial = 0;
  double energy_final = 0;
  double energy_dissipated = 0;  // by dampers, friction and latches up to t_reached
  std::optional<double> energy_driven;  // put in by the drivers up to t_reached (a scene with drivers)
  double t_reached = 0;
  std::vector<std::pair<std::string, double>> final_q;  // joint name, q

  // A free-floating bus (else nullopt): its largest angular rate over the
  // samples (rad/s), the angle of its rotation between the first and the
  // last sample (rad), and the largest change of the system's linear and
  // angular momentum over the samples, each relative to the largest sum
  // of the bodies' own momenta (SystemMomentum's scales).
  struct FreeBus {
    double peak_rate = 0;
    double final_attitude_change = 0;
    double linear_momentum_drift = 0;
    double angular_momentum_drift = 0;
  };
  std::optional<FreeBus> free_bus;
};

// The free bus's figures of a trajectory.
RunSummary::FreeBus summarize_free_bus(const Model& model, const Trajectory& trajectory);

// Stops where *cancel becomes true, incomplete (torque_margins()).
RunSummary summarize(const Scene& scene, const RunResult& result, const std::atomic<bool>* cancel = nullptr);

}  // namespace unfurl::sim
