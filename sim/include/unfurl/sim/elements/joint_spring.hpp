// A torsion (or linear) spring on one joint, with a free position (its
// preload) and viscous damping, or with a measured torque curve:
//   tau = -stiffness (q - free_position) - damping q'   or   curve(q) - damping q'.
#pragma once

#include <memory>

#include "unfurl/sim/elements/joint_element.hpp"
#include "unfurl/sim/elements/spring_curve.hpp"

namespace unfurl::sim {

class JointSpring : public JointElement {
 public:
  using JointElement::JointElement;

  double stiffness = 0;
  double free_position = 0;  // the preload: the spring is relaxed here
  double damping = 0;
  std::shared_ptr<const SpringCurve> curve;  // replaces stiffness and free_position

  double elastic_torque(double q) const { return curve ? curve->torque(q) : -stiffness * (q - free_position); }
  double torque(double q, double dq) const { return elastic_torque(q) - damping * dq; }
  double energy(double q) const {
    return curve ? curve->energy(q) : 0.5 * stiffness * (q - free_position) * (q - free_position);
  }
  // -d tau / dq of the elastic part at q.
  double local_stiffness(double q) const { return curve ? -curve->slope(q) : stiffness; }

  std::string kind() const override { return "spring"; }
  std::string list() const override { return "springs"; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  // spring_torque (the elastic torque), and damper_torque where it damps.
  std::vector<LoadColumn> load_columns(const Model& model) const override;
  void load_values(const ElementState& s, double* values) const override;
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::string note() const override;
};

}  // namespace unfurl::sim
