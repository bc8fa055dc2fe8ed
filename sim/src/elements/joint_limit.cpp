#include "unfurl/sim/elements/joint_limit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "unfurl/sim/number_text.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void JointLimit::add_forces(const ElementState& s, ElementForces& out) const {
  out.Q[w_index(s.model)] += torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

double JointLimit::potential_energy(const ElementState& s) const {
  const double x = penetration(s.q[q_index(s.model)]);
  return 0.5 * stiffness * x * x;
}

// What it takes out beyond the fall of its elastic energy: the damping's
// work, and the elastic torque's where the push-only law drops it.
double JointLimit::dissipated_power(const ElementState& s) const {
  const double q = s.q[q_index(s.model)], w = s.w[w_index(s.model)];
  return -(torque(q, w) - elastic_torque(q)) * w;
}

void JointLimit::add_joint_stiffness(const ElementState& s, RatesOut k, RatesOut c) const {
  if (penetration(s.q[q_index(s.model)]) == 0) return;
  k[w_index(s.model)] += stiffness;
  c[w_index(s.model)] += damping;
}

std::vector<LoadColumn> JointLimit::load_columns(const Model& model) const { return {column(model, "limit_torque")}; }

void JointLimit::load_values(const ElementState& s, double* values) const {
  values[0] = torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

std::string JointLimit::note() const {
  char text[80];
  std::snprintf(text, sizeof text, "range %.4g to %.4g", lower, upper);
  return text;
}

std::vector<ElementParameter> JointLimit::parameters(const Model& model) const {
  const std::string at = " [" + angle_unit(model, joint) + "]";
  std::vector<ElementParameter> p = {
      {"stiffness", "limit stiffness [" + stiffness_unit(model) + "]", stiffness, 0.1 * stiffness, 1e-9, 1e15,
       "how stiffly each end pushes the joint back: tau = -k x - c dq, x past the end"},
      {"damping", "limit damping [" + damping_unit(model) + "]", damping, 0.1 * std::max(damping, 0.01), 0, 1e15,
       "its damping (it never pulls the joint back onto an end)"}};
  if (std::isfinite(lower)) p.push_back({"lower", "lower end" + at, lower, 0.01, 0, 0, "the least angle (or length)"});
  if (std::isfinite(upper))
    p.push_back({"upper", "upper end" + at, upper, 0.01, 0, 0, "the greatest angle (or length)"});
  return p;
}

void JointLimit::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  check_positive(stiffness, field + ".stiffness");
  check_non_negative(damping, field + ".damping");
  if (!(lower < upper))
    throw SceneInvalid(field + ".upper", "the upper end must lie above the lower (" + format_number(lower) + " to " +
                                             format_number(upper) + ")");
}

std::shared_ptr<ForceElement> JointLimit::scaled(double L, double M, const Model& model) const {
  auto l = std::make_shared<JointLimit>(*this);
  l->lower *= angle_scale(model, L);
  l->upper *= angle_scale(model, L);
  l->stiffness *= stiffness_scale(model, L, M);
  l->damping *= stiffness_scale(model, L, M);
  return l;
}

}  // namespace unfurl::sim
