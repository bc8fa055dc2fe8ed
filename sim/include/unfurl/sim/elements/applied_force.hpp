// A constant force and torque applied to a body (a thruster, a test load):
// the force acts at `point` (body frame); both are given in the body frame,
// or in the base frame.
#pragma once

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

class AppliedForce : public ForceElement {
 public:
  int body = 0;
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  Vec3 point = Vec3::Zero();
  bool in_base_frame = false;

  std::string kind() const override { return "applied force"; }
  std::string list() const override { return "applied_forces"; }
  std::string handle(const Model& model) const override { return model.bodies[body].name; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  bool needs_poses() const override { return in_base_frame; }
  std::optional<std::vector<int>> bodies() const override { return bodies_off_base({body}); }
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
};

// (f, m) at a body's origin of a force f at `point` and a torque m.
Vec6 wrench_at_origin(const Vec3& force, const Vec3& torque, const Vec3& point);

}  // namespace unfurl::sim
