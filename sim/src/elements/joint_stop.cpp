#include "unfurl/sim/elements/joint_stop.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void JointStop::add_forces(const ElementState& s, ElementForces& out) const {
  out.Q[w_index(s.model)] += torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

double JointStop::potential_energy(const ElementState& s) const {
  const double x = s.q[q_index(s.model)] - position;
  return 0.5 * stiffness * x * x;
}

double JointStop::dissipated_power(const ElementState& s) const {
  const double w = s.w[w_index(s.model)];
  return damping * w * w;
}

void JointStop::add_joint_stiffness(const ElementState& s, RatesOut k, RatesOut c) const {
  k[w_index(s.model)] += stiffness;
  c[w_index(s.model)] += damping;
}

std::vector<LoadColumn> JointStop::load_columns(const Model& model) const { return {column(model, "stop_torque")}; }

void JointStop::load_values(const ElementState& s, double* values) const {
  values[0] = torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

std::vector<ElementParameter> JointStop::parameters(const Model& model) const {
  return {{"stiffness", "stop stiffness [" + stiffness_unit(model) + "]", stiffness, 0.1 * stiffness, 0, 1e15,
           "how stiffly it holds"},
          {"damping", "stop damping [" + damping_unit(model) + "]", damping, 0.1 * std::max(damping, 0.01), 0, 1e15,
           "its damping"}};
}

void JointStop::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  check_positive(stiffness, field + ".stiffness");
  check_non_negative(damping, field + ".damping");
}

std::shared_ptr<ForceElement> JointStop::scaled(double L, double M, const Model& model) const {
  auto s = std::make_shared<JointStop>(*this);
  s->position *= angle_scale(model, L);
  s->stiffness *= stiffness_scale(model, L, M);
  s->damping *= stiffness_scale(model, L, M);
  return s;
}

}  // namespace unfurl::sim
