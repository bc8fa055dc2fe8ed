#include "unfurl/sim/elements/gravity.hpp"

#include "unfurl/sim/elements/applied_force.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

// A flexible body (docs/FLEXIBLE.md) feels gravity through its first
// moment of mass S(eta) (inertia_invariants.hpp): the potential -m g . x -
// (G g) . S(eta), whose gradients are the force m g at the frame, the
// moment S(eta) x (G g) about it, and B(eta)^T (G g) on the elastic
// coordinates, so the energy balance holds with the deformation.
void Gravity::add_forces(const ElementState& s, ElementForces& out) const {
  for (int i = 0; i < s.model.size(); ++i) {
    const Body& b = s.model.bodies[i];
    if (!b.flexible) {
      out.F[i] += wrench_at_origin(s.poses[i].rotation * (b.mass * g), Vec3::Zero(), b.com);
      continue;
    }
    const flexible::InertiaInvariants& invariants = b.flexible->inertia;
    const Vec3 g_i = s.poses[i].rotation * g;
    const double* eta = s.q.at(PositionIndex{s.model.first_elastic_position[i]});
    out.F[i].head<3>() += invariants.mass() * g_i;
    out.F[i].tail<3>() += invariants.first_moment(eta).cross(g_i);
    invariants.add_field_force(eta, g_i, out.Q.at(VelocityIndex{s.model.first_elastic_velocity[i]}));
  }
}

double Gravity::potential_energy(const ElementState& s) const {
  double V = 0;
  for (int i = 0; i < s.model.size(); ++i) {
    const Body& b = s.model.bodies[i];
    if (!b.flexible) {
      V -= b.mass * g.dot(s.poses[i].to_base(b.com));
      continue;
    }
    const flexible::InertiaInvariants& invariants = b.flexible->inertia;
    const double* eta = s.q.at(PositionIndex{s.model.first_elastic_position[i]});
    V -= invariants.mass() * g.dot(s.poses[i].position) + (s.poses[i].rotation * g).dot(invariants.first_moment(eta));
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
