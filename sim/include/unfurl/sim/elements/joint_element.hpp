// What the elements acting along one revolute or prismatic joint share: the
// joint, how it names them, and the units of their torques (N m, or N on a
// slider) and angles (rad, or m).
#pragma once

#include <string>

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

class JointElement : public ForceElement {
 public:
  explicit JointElement(int joint) : joint(joint) {}

  std::string handle(const Model& model) const override { return model.joints[joint].name; }
  std::optional<std::vector<int>> bodies() const override { return std::vector<int>{}; }  // generalized forces only
  // Its joint is a revolute or prismatic joint of the scene.
  void validate(const Scene& scene, const std::string& field) const override;

  int joint = 0;

 protected:
  // The joint's coordinate in each space.
  PositionIndex q_index(const Model& model) const { return model.position_of(joint); }
  VelocityIndex w_index(const Model& model) const { return model.velocity_of(joint); }
  // "N m" on a hinge, "N" on a slider; "rad" and "m" for its coordinate.
  static std::string torque_unit(const Model& model, int joint);
  static std::string angle_unit(const Model& model, int joint);
  // Its stiffness's and damping's units: per radian on a hinge, per metre
  // on a slider.
  std::string stiffness_unit(const Model& model) const { return slider(model) ? "N/m" : "N m/rad"; }
  std::string damping_unit(const Model& model) const { return slider(model) ? "N s/m" : "N m s/rad"; }
  // How the joint's torque (or force), stiffness and angle (or length)
  // scale with lengths x L and masses x M (ForceElement::scaled).
  double torque_scale(const Model& model, double L, double M) const { return slider(model) ? M * L : M * L * L; }
  double stiffness_scale(const Model& model, double L, double M) const { return slider(model) ? M : M * L * L; }
  double angle_scale(const Model& model, double L) const { return slider(model) ? L : 1.0; }
  bool slider(const Model& model) const { return model.joints[joint].type == JointType::prismatic; }
  // A column listed with the joint.
  LoadColumn column(const Model& model, const std::string& quantity) const {
    return {quantity + "." + model.joints[joint].name, torque_unit(model, joint), "", joint};
  }
};

}  // namespace unfurl::sim
