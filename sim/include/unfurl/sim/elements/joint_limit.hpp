// A joint's range of motion: a hard stop at each end that pushes the joint
// back in and never pulls it (push_only_stop.hpp), nothing inside. What
// catches a panel against its neighbour in the stowed stack or a hinge on
// its bracket; MuJoCo's joint range, Adams' IMPACT on an angle. Unlike a
// stop (joint_stop.hpp), it holds no position; unlike a latch, it is there
// from the start and lets go. No event locates a contact: an end is found
// by the integrator's error control, so the contact's onset costs a few
// rejected steps, as a latch's free play does.
#pragma once

#include <limits>

#include "unfurl/sim/elements/joint_element.hpp"
#include "unfurl/sim/elements/push_only_stop.hpp"

namespace unfurl::sim {

class JointLimit : public JointElement {
 public:
  using JointElement::JointElement;

  // The range (rad, or m); one end may be open.
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double stiffness = 0;  // N m/rad (N/m)
  double damping = 0;    // N m s/rad (N s/m)

  // How far the joint is past an end (signed; 0 within the range).
  double penetration(double q) const { return q > upper ? q - upper : q < lower ? q - lower : 0.0; }
  double elastic_torque(double q) const { return -stiffness * penetration(q); }
  double torque(double q, double q_dot) const { return push_only_torque(penetration(q), q_dot, stiffness, damping); }

  std::string kind() const override { return "limit"; }
  std::string list() const override { return "limits"; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  // Its stiffness and damping while the joint is past an end, else none.
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // limit_torque
  void load_values(const ElementState& s, double* values) const override;
  std::vector<ElementPeak> peaks() const override { return {{"peak_limit_torque", 0, 1}}; }
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::string note() const override;
};

}  // namespace unfurl::sim
