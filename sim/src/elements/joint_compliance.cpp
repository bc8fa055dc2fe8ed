#include "unfurl/sim/elements/joint_compliance.hpp"

#include <cmath>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

std::string JointCompliance::file_path(const Scene& scene) const {
  return "bodies." + scene.model.bodies[joint].name + ".joint.compliance";
}

void JointCompliance::add_forces(const ElementState& s, ElementForces& out) const {
  const int q = s.model.first_position[joint].value + 1, v = s.model.first_velocity[joint].value + 1;
  const auto k = stiffnesses(), c = dampings();
  for (int m = 0; m < 5; ++m) out.Q[VelocityIndex{v + m}] -= k[m] * s.q[PositionIndex{q + m}] + c[m] * s.w[VelocityIndex{v + m}];
}

double JointCompliance::potential_energy(const ElementState& s) const {
  const int q = s.model.first_position[joint].value + 1;
  const auto k = stiffnesses();
  double V = 0;
  for (int m = 0; m < 5; ++m) V += 0.5 * k[m] * std::pow(s.q[PositionIndex{q + m}], 2);
  return V;
}

double JointCompliance::dissipated_power(const ElementState& s) const {
  const int v = s.model.first_velocity[joint].value + 1;
  const auto c = dampings();
  double P = 0;
  for (int m = 0; m < 5; ++m) P += c[m] * std::pow(s.w[VelocityIndex{v + m}], 2);
  return P;
}

void JointCompliance::add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const {
  const int v = s.model.first_velocity[joint].value + 1;
  const auto k = stiffnesses(), c = dampings();
  for (int m = 0; m < 5; ++m) {
    stiffness[VelocityIndex{v + m}] += k[m];
    damping[VelocityIndex{v + m}] += c[m];
  }
}

std::shared_ptr<ForceElement> JointCompliance::scaled(double L, double M, const Model&) const {
  // A force per length (N/m) scales as M, a torque per radian as M L^2.
  auto s = std::make_shared<JointCompliance>(*this);
  s->radial *= M, s->axial *= M, s->radial_damping *= M, s->axial_damping *= M;
  s->tilt *= M * L * L, s->tilt_damping *= M * L * L;
  return s;
}

void JointCompliance::validate(const Scene& scene, const std::string& field) const {
  if (joint < 0 || joint >= scene.model.size()) throw SceneInvalid(field, "no such joint");
  const Joint& j = scene.model.joints[joint];
  if (j.type != JointType::revolute || !j.compliant)
    throw SceneInvalid(field, "compliance is for revolute joints ('" + j.name + "' is " + joint_type_name(j.type) + ")");
  const std::pair<const char*, double> values[] = {{"radial", radial}, {"axial", axial}, {"tilt", tilt}};
  for (const auto& [name, k] : values)
    if (!std::isfinite(k) || !(k > 0))
      throw SceneInvalid(field + "." + name,
                         "must be positive: a pin without stiffness there is a constraint left out (give the joint "
                         "another type, or a soft value)");
  const std::pair<const char*, double> dampers[] = {
      {"radial_damping", radial_damping}, {"axial_damping", axial_damping}, {"tilt_damping", tilt_damping}};
  for (const auto& [name, c] : dampers)
    if (!std::isfinite(c) || c < 0) throw SceneInvalid(field + "." + name, "must not be negative");
}

std::vector<ElementParameter> JointCompliance::parameters(const Model& /*model*/) const {
  return {{"radial", "radial stiffness [N/m]", radial, 0.1 * radial, 0, 1e15, "the pin's stiffness across the axis"},
          {"axial", "axial stiffness [N/m]", axial, 0.1 * axial, 0, 1e15, "the pin's stiffness along the axis"},
          {"tilt", "tilt stiffness [N m/rad]", tilt, 0.1 * tilt, 0, 1e15, "the pin's stiffness against tilting"},
          {"radial_damping", "radial damping [N s/m]", radial_damping, 0.1 * std::max(radial_damping, 1.0), 0, 1e15,
           "the pin's damping across the axis"},
          {"axial_damping", "axial damping [N s/m]", axial_damping, 0.1 * std::max(axial_damping, 1.0), 0, 1e15,
           "the pin's damping along the axis"},
          {"tilt_damping", "tilt damping [N m s/rad]", tilt_damping, 0.1 * std::max(tilt_damping, 0.01), 0, 1e15,
           "the pin's damping against tilting"}};
}

}  // namespace unfurl::sim
