#include "unfurl/sim/elements/elasticity.hpp"

#include <cstdio>

#include "unfurl/sim/number_text.hpp"
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

std::vector<ElementParameter> Elasticity::parameters(const Model& /*model*/) const {
  const std::optional<flexible::PlateBodySpec>& plate = flexible_->plate;
  std::vector<ElementParameter> out;
  const std::optional<flexible::FemBodySpec>& fem = flexible_->fem;
  const flexible::ModalDamping& d = fem ? fem->damping : plate ? plate->damping : flexible_->beam.damping;
  const bool file_damping = fem && fem->damping_from_file;  // the FE file's matrix, not the scene's
  if (!file_damping && d.is_uniform()) {
    out.push_back({"damping", "damping ratio", d.bands[0].ratio, 0.001, 0, 0.99,
                   "every elastic coordinate's modal damping ratio zeta"});
  } else if (!file_damping && d.per_coordinate.empty()) {
    for (std::size_t k = 0; k < d.bands.size(); ++k) {
      const bool last = k + 1 == d.bands.size();
      const std::string edge = format_number(last ? d.bands[k - 1].up_to_hz : d.bands[k].up_to_hz);
      out.push_back({"damping." + std::to_string(k) + ".ratio", std::string("zeta ") + (last ? "above " : "to ") + edge + " Hz",
                     d.bands[k].ratio, 0.001, 0, 0.99,
                     "the modal damping ratio of the elastic coordinates in this band of frequencies"});
    }
  }
  if (fem) return out;  // its stiffness and mass are the FE model's
  if (plate) {
    const flexible::PlateSpec& p = plate->plate;
    if (plate->youngs_modulus > 0)
      out.push_back({"plate.youngs_modulus", "E [Pa]", plate->youngs_modulus, 0.01 * plate->youngs_modulus, 0, 1e15,
                     "the plate's Young's modulus (its thickness held)"});
    else
      out.push_back({"plate.bending_stiffness", "D [N m]", p.bending_stiffness, 0.01 * p.bending_stiffness, 0, 1e15,
                     "the plate's bending stiffness E t^3 / (12 (1 - nu^2))"});
    out.push_back({"plate.mass_per_area", "mass [kg/m^2]", p.mass_per_area, 0.01 * p.mass_per_area, 0, 1e9,
                   "the plate's mass per area"});
    return out;
  }
  const flexible::BeamSection& s = flexible_->beam.section;
  if (s.bending_stiffness_y == s.bending_stiffness_z)
    out.push_back({"beam.bending_stiffness", "EI [N m^2]", s.bending_stiffness_z, 0.01 * s.bending_stiffness_z, 0,
                   1e15, "the beam's bending stiffness in both planes"});
  out.push_back({"beam.mass_per_length", "rho A [kg/m]", s.mass_per_length, 0.01 * s.mass_per_length, 0, 1e9,
                 "the beam's mass per length"});
  return out;
}

std::string Elasticity::note() const {
  const Eigen::VectorXd& f = flexible_->frequency_hz;
  char text[96];
  std::snprintf(text, sizeof text, "%d elastic coordinates, %.4g .. %.4g Hz with the frame held", flexible_->modes(),
                f.size() ? f.minCoeff() : 0.0, f.size() ? f.maxCoeff() : 0.0);
  return text;
}

// The body's structure is scaled with the body (studies::scale_scene);
// the element follows it.
std::shared_ptr<ForceElement> Elasticity::scaled(double, double, const Model& model) const {
  return std::make_shared<Elasticity>(body_, model.bodies[body_].flexible);
}

}  // namespace unfurl::sim
