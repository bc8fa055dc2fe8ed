// A viscous damper on one joint: tau = -damping q'.
#pragma once

#include "unfurl/sim/elements/joint_element.hpp"

namespace unfurl::sim {

class JointDamper : public JointElement {
 public:
  using JointElement::JointElement;

  double damping = 0;

  std::string kind() const override { return "damper"; }
  std::string list() const override { return "dampers"; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // damper_torque
  void load_values(const ElementState& s, double* values) const override;
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
};

}  // namespace unfurl::sim
