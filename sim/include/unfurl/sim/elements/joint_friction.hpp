// Hinge friction: Coulomb plus viscous, with the Coulomb part smoothed near
// zero speed so the right-hand side stays smooth and the integrators keep
// their order.
#pragma once

#include <cmath>

#include "unfurl/sim/elements/joint_element.hpp"

namespace unfurl::sim {

// tau_f = -coulomb tanh(dq / velocity_scale) - viscous dq on one joint.
// Within |dq| < velocity_scale the Coulomb torque ramps through zero (its
// slope there is coulomb / velocity_scale): a stuck joint creeps at about
// velocity_scale * (applied torque / coulomb) instead of sticking, which is
// the price of a smooth law. Choose velocity_scale well below the speeds
// that matter (the default, 1e-3 rad/s, is 0.06 deg/s).
class JointFriction : public JointElement {
 public:
  using JointElement::JointElement;

  double coulomb = 0;            // N m (N for a slider): the sliding friction torque
  double viscous = 0;            // N m s/rad
  double velocity_scale = 1e-3;  // rad/s (m/s)

  double torque(double dq) const { return -coulomb * std::tanh(dq / velocity_scale) - viscous * dq; }
  // The power it takes out of the mechanism, -tau_f dq >= 0.
  double dissipation(double dq) const { return -torque(dq) * dq; }

  std::string kind() const override { return "friction"; }
  std::string list() const override { return "friction"; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double dissipated_power(const ElementState& s) const override { return dissipation(s.w[w_index(s.model)]); }
  bool dissipative() const override { return true; }
  // Its slope at the state's rate as damping.
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // friction_torque
  void load_values(const ElementState& s, double* values) const override;
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
};

}  // namespace unfurl::sim
