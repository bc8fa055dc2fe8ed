// A stop that holds one joint at a position from the start: tau = -k (q -
// position) - c q'. What a stuck hinge or a launch lock is; a study's
// `stuck` failure injects one. It is not a latch (it engages nothing and
// has no event), so a stuck hinge's latch stays unlatched and the case is
// reported not deployed; its torque is `stop_torque.J` in loads.csv.
#pragma once

#include "unfurl/sim/elements/joint_element.hpp"

namespace unfurl::sim {

class JointStop : public JointElement {
 public:
  using JointElement::JointElement;

  double position = 0;   // where it holds the joint (rad, or m)
  double stiffness = 0;  // N m/rad (N/m)
  double damping = 0;    // N m s/rad (N s/m)

  double torque(double q, double q_dot) const { return -stiffness * (q - position) - damping * q_dot; }

  std::string kind() const override { return "stop"; }
  std::string list() const override { return "stops"; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // stop_torque
  void load_values(const ElementState& s, double* values) const override;
  std::vector<ElementPeak> peaks() const override { return {{"peak_stop_torque", 0, 1}}; }
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
};

}  // namespace unfurl::sim
