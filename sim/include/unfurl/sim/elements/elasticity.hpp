// A flexible body's own elasticity: on its elastic coordinates eta (unit
// modal masses) Q = -K eta - D eta', K = diag(omega_k^2), D = diag(2 zeta_k
// omega_k); stored energy eta^T K eta / 2, dissipated power eta'^T D eta'.
// One per flexible body, made with the body (SceneBuilder::body).
#pragma once

#include <memory>

#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

class Elasticity : public ForceElement {
 public:
  Elasticity(int body, std::shared_ptr<const flexible::FlexibleBody> flexible)
      : body_(body), flexible_(std::move(flexible)) {}

  int body() const { return body_; }
  std::string kind() const override { return "elasticity"; }
  std::string list() const override { return "bodies"; }
  std::string handle(const Model& model) const override { return model.bodies[body_].name; }
  std::string file_path(const Scene& scene) const override;
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::optional<std::vector<int>> bodies() const override { return std::vector<int>{}; }  // generalized forces only
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return true; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // elastic_energy, deflection
  void load_values(const ElementState& s, double* values) const override;
  // The largest deflection, as a fraction of the body's size, the model is
  // meant for: its kinetic energy is kept to second order in the
  // deformation and its stiffness is linear, so their errors grow as the
  // square of it (a per cent at a tenth); a run beyond is warned about.
  static constexpr double kLargeDeflection = 0.1;
  // peak_deflection: the largest displacement of its mesh over the run.
  std::vector<ElementPeak> peaks() const override { return {{"peak_deflection", 1, 1}}; }
  // The damping ratio, and the beam's bending stiffness (when both planes'
  // are equal) and mass per length: edited, the body is meshed and
  // reduced again.
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::string note() const override;  // its coordinates and their frequencies
  // On the model's (already scaled) structure of the body.
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;

 private:
  int body_;
  std::shared_ptr<const flexible::FlexibleBody> flexible_;
};

}  // namespace unfurl::sim
