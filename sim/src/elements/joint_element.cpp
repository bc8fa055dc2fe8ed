#include "unfurl/sim/elements/joint_element.hpp"

namespace unfurl {

std::string JointElement::torque_unit(const Model& model, int joint) {
  return model.joints[joint].type == JointType::prismatic ? "N" : "N m";
}

std::string JointElement::angle_unit(const Model& model, int joint) {
  return model.joints[joint].type == JointType::prismatic ? "m" : "rad";
}

}  // namespace unfurl
