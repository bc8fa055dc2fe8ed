#include "unfurl/sim/elements/joint_friction.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void JointFriction::add_forces(const ElementState& s, ElementForces& out) const {
  out.Q[w_index(s.model)] += torque(s.w[w_index(s.model)]);
}

void JointFriction::add_joint_stiffness(const ElementState& s, RatesOut, RatesOut c) const {
  // The tanh's slope; 0 far out on its flat part (no inf * 0).
  const double x = s.w[w_index(s.model)] / velocity_scale;
  const double sech = std::abs(x) < 30 ? 1 / std::cosh(x) : 0.0;
  c[w_index(s.model)] += viscous + coulomb * (sech * sech / velocity_scale);
}

std::vector<LoadColumn> JointFriction::load_columns(const Model& model) const {
  return {column(model, "friction_torque")};
}

void JointFriction::load_values(const ElementState& s, double* values) const {
  values[0] = torque(s.w[w_index(s.model)]);
}

std::vector<ElementParameter> JointFriction::parameters(const Model& model) const {
  return {{"coulomb", "Coulomb [" + torque_unit(model, joint) + "]", coulomb, 0.001, 0, 1e9,
           "sliding friction torque T_c: tau = -T_c tanh(dq / v_s) - c_v dq"},
          {"viscous", "viscous [" + damping_unit(model) + "]", viscous, 0.001, 0, 1e9,
           "viscous friction coefficient c_v"},
          {"velocity_scale", "velocity scale [" + angle_unit(model, joint) + "/s]", velocity_scale, 1e-4, 1e-9, 1e3,
           "v_s: the Coulomb torque ramps through zero speed over about this rate"}};
}

void JointFriction::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  check_non_negative(coulomb, field + ".coulomb");
  check_non_negative(viscous, field + ".viscous");
  check_positive(velocity_scale, field + ".velocity_scale");
  if (velocity_scale < 1e-9)
    throw SceneInvalid(field + ".velocity_scale",
                       "below 1e-9 rad/s the smoothed friction is a step no integrator can follow");
}

std::shared_ptr<ForceElement> JointFriction::scaled(double L, double M, const Model& model) const {
  auto f = std::make_shared<JointFriction>(*this);
  f->coulomb *= torque_scale(model, L, M);
  f->viscous *= stiffness_scale(model, L, M);
  f->velocity_scale *= angle_scale(model, L);
  return f;
}

}  // namespace unfurl::sim
