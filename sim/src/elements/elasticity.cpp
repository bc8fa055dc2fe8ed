#include "unfurl/sim/elements/elasticity.hpp"

#include <stdexcept>

#include "unfurl/sim/scene.hpp"

namespace unfurl::sim {
namespace {

const flexible::FlexibleBody& flexible_of(const Model& model, int body) { return *model.bodies[body].flexible; }

}  // namespace

std::string Elasticity::file_path(const Scene& scene) const {
  return "bodies." + scene.model.bodies[body_].name + ".flexible";
}

void Elasticity::add_forces(const ElementState& s, ElementForces& out) const {
  const flexible::FlexibleBody& f = flexible_of(s.model, body_);
  const int e = s.model.first_elastic_velocity[body_], c = s.model.first_elastic_position[body_];
  for (int k = 0; k < f.modes(); ++k)
    out.Q[VelocityIndex{e + k}] -= f.stiffness[k] * s.q[PositionIndex{c + k}] + f.damping[k] * s.w[VelocityIndex{e + k}];
}

double Elasticity::potential_energy(const ElementState& s) const {
  const flexible::FlexibleBody& f = flexible_of(s.model, body_);
  const int c = s.model.first_elastic_position[body_];
  double V = 0;
  for (int k = 0; k < f.modes(); ++k) V += 0.5 * f.stiffness[k] * s.q[PositionIndex{c + k}] * s.q[PositionIndex{c + k}];
  return V;
}

double Elasticity::dissipated_power(const ElementState& s) const {
  const flexible::FlexibleBody& f = flexible_of(s.model, body_);
  const int e = s.model.first_elastic_velocity[body_];
  double P = 0;
  for (int k = 0; k < f.modes(); ++k) P += f.damping[k] * s.w[VelocityIndex{e + k}] * s.w[VelocityIndex{e + k}];
  return P;
}

void Elasticity::add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const {
  const flexible::FlexibleBody& f = flexible_of(s.model, body_);
  const int e = s.model.first_elastic_velocity[body_];
  for (int k = 0; k < f.modes(); ++k) {
    stiffness[VelocityIndex{e + k}] += f.stiffness[k];
    damping[VelocityIndex{e + k}] += f.damping[k];
  }
}

std::vector<LoadColumn> Elasticity::load_columns(const Model& model) const {
  const std::string& name = model.bodies[body_].name;
  return {{"elastic_energy." + name, "J", ""}, {"deflection." + name, "m", ""}};
}

void Elasticity::load_values(const ElementState& s, double* values) const {
  values[0] = potential_energy(s);
  values[1] = flexible_of(s.model, body_).largest_deflection(&s.q[PositionIndex{s.model.first_elastic_position[body_]}]);
}

std::shared_ptr<ForceElement> Elasticity::scaled(double, double, const Model&) const {
  throw std::invalid_argument("a scene with flexible bodies cannot be scaled yet");
}

}  // namespace unfurl::sim
