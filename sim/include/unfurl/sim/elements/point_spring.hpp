// Point-to-point spring-dampers and cables: a force along the line between
// a point on one body and a point on another body (or the base).
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

struct PointFrame;

// Where a point spring is: its length, its rate, and the unit vector from
// a to b (zero at zero length, where the line has no direction), base frame.
struct PointSpringGeometry {
  double length = 0, rate = 0;
  Vec3 a = Vec3::Zero(), b = Vec3::Zero(), direction = Vec3::Zero();
};

// Tension T = stiffness (L - rest_length) + damping dL/dt (> 0 pulls the
// points together). A cable (tension_only) carries no compression: T =
// max(0, ...) while taut and 0 while slack (L <= rest_length).
class PointSpring : public ForceElement {
 public:
  std::string name;
  bool named = false;                  // the name was given (else it is made up and the element is addressed by index)
  int body_a = kBase, body_b = kBase;  // kBase: a point fixed on the base
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero();  // in each body's frame
  double stiffness = 0;                                 // N/m
  double rest_length = 0;                               // m: the preload is stiffness (L0 - rest_length)
  double damping = 0;                                   // N s/m
  bool tension_only = false;

  bool slack(double L) const { return tension_only && L <= rest_length; }
  // The elastic part of the tension, and the stored energy.
  double elastic(double L) const { return slack(L) ? 0.0 : stiffness * (L - rest_length); }
  double energy(double L) const { return slack(L) ? 0.0 : 0.5 * stiffness * (L - rest_length) * (L - rest_length); }
  double tension(double L, double L_dot) const {
    if (slack(L)) return 0.0;
    const double T = elastic(L) + damping * L_dot;
    return tension_only && T < 0 ? 0.0 : T;
  }
  // Between its two points at a state, or between two given frames.
  PointSpringGeometry geometry(const ElementState& s) const;
  PointSpringGeometry geometry(const PointFrame& a, const PointFrame& b) const;

  std::string kind() const override { return tension_only ? "cable" : "point spring"; }
  std::string list() const override { return "point_springs"; }
  std::string handle(const Model&) const override { return named ? name : ""; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  bool needs_poses() const override { return true; }
  std::optional<std::vector<int>> bodies() const override { return bodies_off_base({body_a, body_b}); }
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // tension
  void load_values(const ElementState& s, double* values) const override;
  // A valid name of its own, two distinct bodies, non-negative values, and
  // two points apart at the initial state (the force needs a direction).
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::vector<ElementLink> links() const override {
    return {{body_a, body_b, point_a, point_b, tension_only ? ElementLink::Style::cable : ElementLink::Style::spring}};
  }
};

}  // namespace unfurl::sim
