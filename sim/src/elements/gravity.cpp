#include "unfurl/sim/elements/gravity.hpp"

#include "unfurl/sim/elements/applied_force.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void Gravity::add_forces(const ElementState& s, ElementForces& out) const {
  for (int i = 0; i < s.model.size(); ++i) {
    const Body& b = s.model.bodies[i];
    out.F[i] += wrench_at_origin(s.poses[i].rotation * (b.mass * g), Vec3::Zero(), b.com);
  }
}

double Gravity::potential_energy(const ElementState& s) const {
  double V = 0;
  for (int i = 0; i < s.model.size(); ++i) {
    const Body& b = s.model.bodies[i];
    V -= b.mass * g.dot(s.poses[i].to_base(b.com));
  }
  return V;
}

void Gravity::validate(const Scene& scene, const std::string&) const {
  if (!g.isZero(0) && scene.model.base_rotates())
    throw SceneInvalid("gravity", "gravity needs a base that does not rotate");
}

std::shared_ptr<ForceElement> Gravity::scaled(double L, double, const Model&) const {
  return std::make_shared<Gravity>(g * L);
}

}  // namespace unfurl::sim
