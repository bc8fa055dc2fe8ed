#include "unfurl/sim/summary.hpp"
#include "unfurl/sim/elements/joint_driver.hpp"

#include <algorithm>
#include <limits>

namespace unfurl::sim {

RunSummary summarize(const Scene& scene, const RunResult& result, const std::atomic<bool>* cancel) {
  RunSummary s;
  const Model& model = scene.model;
  const Trajectory& tr = result.trajectory;
  for (const LatchEvent& e : tr.events) s.latch_times.emplace_back(model.joints[e.joint].name, e.t);
  const std::vector<const Latch*> latches = scene.latches();
  for (int l = 0; l < static_cast<int>(latches.size()); ++l) {
    const bool engaged = std::any_of(tr.events.begin(), tr.events.end(),
                                     [&](const LatchEvent& e) { return e.latch == l; });
    if (!engaged) s.unlatched.push_back(model.joints[latches[l]->joint].name);
  }
  const RunPeaks& p = result.peaks;
  s.max_closure_gap = p.gap_m.value;
  s.max_closure_angle = p.gap_rad.value;
  s.max_closure_gap_before_latch = p.gap_m_before_latch.value;
  s.max_closure_angle_before_latch = p.gap_rad_before_latch.value;
  for (std::size_t l = 0; l < p.latch_torque.size(); ++l)
    s.peak_latch_torque.push_back({model.joints[latches[l]->joint].name, p.latch_torque[l]});
  for (std::size_t j = 0; j < p.hinge_force.size(); ++j) {
    if (!model.joints[j].has_reaction()) continue;
    s.peak_hinge_force.push_back({model.joints[j].name, p.hinge_force[j]});
    s.peak_hinge_moment.push_back({model.joints[j].name, p.hinge_moment[j]});
    s.peak_hinge_force_indeterminate.push_back({model.joints[j].name, p.hinge_force_indeterminate[j]});
    s.peak_hinge_moment_indeterminate.push_back({model.joints[j].name, p.hinge_moment_indeterminate[j]});
  }
  const std::vector<TrackedPeak> tracked = scene.element_peaks();
  for (std::size_t k = 0; k < p.element.size() && k < tracked.size(); ++k)
    s.element_peaks.push_back({tracked[k].quantity, tracked[k].name, tracked[k].unit, p.element[k]});
  const std::vector<TrackedPeak> sensors = scene.sensor_peaks();
  for (std::size_t k = 0; k < p.sensor.size() && k < sensors.size(); ++k)
    s.sensor_peaks.push_back({sensors[k].quantity, sensors[k].name, sensors[k].unit, p.sensor[k]});
  s.indeterminate_spans = p.indeterminate_spans;
  if (p.loads_assessed) s.loads_determinate = p.indeterminate_spans.empty();
  s.torque_margin_factors = scene.torque_margin;
  s.torque_margins = torque_margins(scene, tr, cancel);
  if (cancel && cancel->load()) {
    s.interrupted = true;
    s.torque_margins.clear();
  }
  if (!tr.empty()) {
    s.energy_initial = tr.samples.front().energy.total();
    s.energy_final = tr.samples.back().energy.total();
    s.energy_dissipated = tr.samples.back().energy.dissipated;
    if (!scene.elements_of<JointDriver>().empty()) s.energy_driven = tr.samples.back().energy.driven;
    s.t_reached = tr.samples.back().t;
    for (int c = 0; c < model.nq; ++c)
      s.final_q.emplace_back(model.position_name(c), tr.samples.back().y[tr.layout.q() + c]);
    if (model.free_floating()) s.free_bus = summarize_free_bus(model, tr);
  }
  return s;
}

double RunSummary::worst_motorization_factor() const {
  double worst = std::numeric_limits<double>::infinity();
  for (const JointTorqueMargin& m : torque_margins) worst = std::min(worst, m.worst());
  return worst;
}

RunSummary::FreeBus summarize_free_bus(const Model& model, const Trajectory& tr) {
  RunSummary::FreeBus bus;
  const Sample& first = tr.samples.front();
  const Eigen::Vector4d start = bus_motion(model, first.y.data() + tr.layout.q(), first.q_dot.data()).quaternion;
  double linear_scale = 0, angular_scale = 0, linear_change = 0, angular_change = 0;
  for (const Sample& s : tr.samples) {
    const JointOrientation motion = bus_motion(model, s.y.data() + tr.layout.q(), s.q_dot.data());
    bus.peak_rate = std::max(bus.peak_rate, motion.rate.norm());
    bus.final_attitude_change = rotation_angle_between(start, motion.quaternion);
    linear_scale = std::max(linear_scale, s.momentum.linear_scale);
    angular_scale = std::max(angular_scale, s.momentum.angular_scale);
    linear_change = std::max(linear_change, (s.momentum.linear - first.momentum.linear).norm());
    angular_change = std::max(angular_change, (s.momentum.angular - first.momentum.angular).norm());
  }
  bus.linear_momentum_drift = linear_scale > 0 ? linear_change / linear_scale : 0;
  bus.angular_momentum_drift = angular_scale > 0 ? angular_change / angular_scale : 0;
  return bus;
}

}  // namespace unfurl::sim
