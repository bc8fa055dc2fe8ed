#include "unfurl/sim/elements/joint_spring.hpp"

#include <algorithm>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void JointSpring::add_forces(const ElementState& s, ElementForces& out) const {
  out.Q[w_index(s.model)] += torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

double JointSpring::potential_energy(const ElementState& s) const { return energy(s.q[q_index(s.model)]); }

double JointSpring::dissipated_power(const ElementState& s) const {
  const double w = s.w[w_index(s.model)];
  return damping * w * w;
}

void JointSpring::add_joint_stiffness(const ElementState& s, RatesOut k, RatesOut c) const {
  const VelocityIndex v = w_index(s.model);
  k[v] += std::max(0.0, local_stiffness(s.q[q_index(s.model)]));  // a rising stretch of a curve: none
  c[v] += damping;
}

std::vector<LoadColumn> JointSpring::load_columns(const Model& model) const {
  std::vector<LoadColumn> columns{column(model, "spring_torque")};
  if (damping != 0) columns.push_back(column(model, "damper_torque"));
  return columns;
}

void JointSpring::load_values(const ElementState& s, double* values) const {
  values[0] = elastic_torque(s.q[q_index(s.model)]);
  if (damping != 0) values[1] = -damping * s.w[w_index(s.model)];
}

std::string JointSpring::note() const {
  return curve ? "measured curve, " + std::to_string(curve->angles().size()) + " points (edit the file's table)" : "";
}

std::vector<ElementParameter> JointSpring::parameters(const Model& model) const {
  std::vector<ElementParameter> p;
  if (!curve) {
    p.push_back({"stiffness", "stiffness [" + stiffness_unit(model) + "]", stiffness, 0.005, 0, 1e9,
                 "torsion spring rate k: tau = -k (q - free angle) - c dq"});
    const std::string free = slider(model) ? "preload: free length [m]" : "preload: free angle [rad]";
    p.push_back({"free_position", free, free_position, 0.01, 0, 0,
                 "the angle where the spring is relaxed; the preload at q is k (free angle - q)"});
  }
  p.push_back(
      {"damping", "damping [" + damping_unit(model) + "]", damping, 0.001, 0, 1e9, "viscous damping c of the hinge"});
  return p;
}

void JointSpring::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  if (!curve) check_non_negative(stiffness, field + ".stiffness");
  check_non_negative(damping, field + ".damping");
}

std::shared_ptr<ForceElement> JointSpring::scaled(double L, double M, const Model& model) const {
  auto s = std::make_shared<JointSpring>(*this);
  s->stiffness *= stiffness_scale(model, L, M);
  s->free_position *= angle_scale(model, L);
  s->damping *= stiffness_scale(model, L, M);
  if (curve) {
    std::vector<double> q = curve->angles(), tau = curve->torques();
    for (double& x : q) x *= angle_scale(model, L);
    for (double& x : tau) x *= torque_scale(model, L, M);
    s->curve = std::make_shared<const SpringCurve>(q, tau);
  }
  return s;
}

}  // namespace unfurl::sim
