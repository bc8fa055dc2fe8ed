#include "unfurl/sim/elements/joint_damper.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void JointDamper::add_forces(const ElementState& s, ElementForces& out) const {
  out.Q[w_index(s.model)] += -damping * s.w[w_index(s.model)];
}

double JointDamper::dissipated_power(const ElementState& s) const {
  const double w = s.w[w_index(s.model)];
  return damping * w * w;
}

void JointDamper::add_joint_stiffness(const ElementState& s, RatesOut, RatesOut c) const {
  c[w_index(s.model)] += damping;
}

std::vector<LoadColumn> JointDamper::load_columns(const Model& model) const { return {column(model, "damper_torque")}; }

void JointDamper::load_values(const ElementState& s, double* values) const {
  values[0] = -damping * s.w[w_index(s.model)];
}

std::vector<ElementParameter> JointDamper::parameters(const Model& model) const {
  return {
      {"damping", "damping [" + damping_unit(model) + "]", damping, 0.001, 0, 1e9, "viscous damping c of the hinge"}};
}

void JointDamper::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  check_non_negative(damping, field + ".damping");
}

std::shared_ptr<ForceElement> JointDamper::scaled(double L, double M, const Model& model) const {
  auto d = std::make_shared<JointDamper>(*this);
  d->damping *= stiffness_scale(model, L, M);
  return d;
}

}  // namespace unfurl::sim
