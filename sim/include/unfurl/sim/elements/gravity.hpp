// Uniform gravity: m g on every body at its centre of mass, g given in the
// base (inertial) frame, which must not rotate; on a flexible body, on
// every mass point of its deformed shape.
#pragma once

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

class Gravity : public ForceElement {
 public:
  explicit Gravity(const Vec3& g) : g(g) {}

  Vec3 g;  // m/s^2, base frame

  std::string kind() const override { return "gravity"; }
  std::string list() const override { return "gravity"; }
  std::string handle(const Model&) const override { return ""; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  bool needs_poses() const override { return true; }
  // -sum m_i g . r_c,i (a flexible body's centre of mass deformed)
  double potential_energy(const ElementState& s) const override;
  EnergyStore energy_store() const override { return EnergyStore::gravity; }
  // A base that does not rotate (g is given in its frame).
  void validate(const Scene& scene, const std::string& field) const override;
};

}  // namespace unfurl::sim
