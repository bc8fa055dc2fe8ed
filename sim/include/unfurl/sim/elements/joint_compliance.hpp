// The pin of a compliant hinge (joint.hpp): springs and dampers on its five
// compliant coordinates, given as a bearing's are, radial (u1, u2: across
// the axis), axial (ua) and tilt (r1, r2): Q = -k x - c x' on each. Its
// energy counts in the springs' store and its damping's work in the
// dissipation; the forces it carries are the joint's reaction, reported in
// hinge_force.J and hinge_moment.J as a rigid hinge's are. Written in the
// scene file as the joint's `compliance:`.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

class JointCompliance : public ForceElement {
 public:
  int joint = 0;
  double radial = 0, axial = 0, tilt = 0;  // N/m, N/m, N m/rad
  double radial_damping = 0, axial_damping = 0, tilt_damping = 0;  // N s/m, N s/m, N m s/rad

  // The five coordinates' stiffness and damping, (u1, u2, ua, r1, r2).
  std::array<double, 5> stiffnesses() const { return {radial, radial, axial, tilt, tilt}; }
  std::array<double, 5> dampings() const {
    return {radial_damping, radial_damping, axial_damping, tilt_damping, tilt_damping};
  }

  std::string kind() const override { return "compliance"; }
  std::string list() const override { return "compliance"; }
  std::string handle(const Model& model) const override { return model.joints[joint].name; }
  std::string file_path(const Scene& scene) const override;
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::optional<std::vector<int>> bodies() const override { return std::vector<int>{}; }  // generalized forces only
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return radial_damping > 0 || axial_damping > 0 || tilt_damping > 0; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  // On a compliant revolute joint; stiffness positive, damping not
  // negative (a pin without stiffness is a constraint left out).
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
};

}  // namespace unfurl::sim
