#include "unfurl/sim/elements/joint_element.hpp"

#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

std::string JointElement::torque_unit(const Model& model, int joint) {
  return model.joints[joint].type == JointType::prismatic ? "N" : "N m";
}

std::string JointElement::angle_unit(const Model& model, int joint) {
  return model.joints[joint].type == JointType::prismatic ? "m" : "rad";
}

void JointElement::validate(const Scene& scene, const std::string& field) const {
  if (joint < 0 || joint >= scene.model.size()) throw SceneInvalid(field + ".joint", "no such joint");
  const Joint& j = scene.model.joints[joint];
  if (j.dof() == 0) throw SceneInvalid(field + ".joint", "joint '" + j.name + "' is fixed: it has no coordinate");
  if (!j.has_free_coordinate())
    throw SceneInvalid(field + ".joint",
                       "joint '" + j.name + "' is " + joint_type_name(j.type) +
                           ": springs, dampers, friction, latches and drivers act on revolute and prismatic joints");
}

}  // namespace unfurl::sim
