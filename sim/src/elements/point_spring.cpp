#include "unfurl/sim/elements/point_spring.hpp"

#include "unfurl/sim/elements/point_frame.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {


PointSpringGeometry PointSpring::geometry(const PointFrame& a, const PointFrame& b) const {
  PointSpringGeometry g;
  g.a = a.position();
  g.b = b.position();
  const Vec3 d = g.b - g.a;
  g.length = d.norm();
  if (g.length > 1e-12) g.direction = d / g.length;
  g.rate = g.direction.dot(b.velocity() - a.velocity());
  return g;
}

PointSpringGeometry PointSpring::geometry(const ElementState& s) const {
  return geometry(point_frame(s, body_a, point_a), point_frame(s, body_b, point_b));
}

void PointSpring::add_forces(const ElementState& s, ElementForces& out) const {
  const PointFrame a = point_frame(s, body_a, point_a), b = point_frame(s, body_b, point_b);
  const PointSpringGeometry g = geometry(a, b);
  const double T = tension(g.length, g.rate);
  add_point_force(s, a, T * g.direction, out);
  add_point_force(s, b, -T * g.direction, out);
}

double PointSpring::potential_energy(const ElementState& s) const {
  return energy(geometry(s).length);
}

double PointSpring::dissipated_power(const ElementState& s) const {
  const PointSpringGeometry g = geometry(s);
  return (tension(g.length, g.rate) - elastic(g.length)) * g.rate;
}

std::vector<LoadColumn> PointSpring::load_columns(const Model&) const { return {{"tension." + name, "N", "", -1}}; }

void PointSpring::load_values(const ElementState& s, double* values) const {
  const PointSpringGeometry g = geometry(s);
  values[0] = tension(g.length, g.rate);
}

std::vector<ElementParameter> PointSpring::parameters(const Model& /*model*/) const {
  return {{"stiffness", "stiffness [N/m]", stiffness, 0.1, 0, 1e12,
           "T = k (L - rest length) + c dL/dt between the two points"},
          {"rest_length", "rest length [m]", rest_length, 0.001, 0, 1e6,
           "the length at which it pulls nothing (a cable is slack below it)"},
          {"damping", "damping [N s/m]", damping, 0.01, 0, 1e12, "damping c along the line"}};
}

void PointSpring::validate(const Scene& scene, const std::string& field) const {
  if (named && !is_valid_name(name))
    throw SceneInvalid(
        field + ".name",
        "the name '" + name + "' has characters other than letters, digits, '_' and '-' (or is empty or over 64)");
  for (const PointSpring* other : scene.elements_of<PointSpring>()) {
    if (other == this) break;
    if (other->name == name) throw SceneInvalid(field + ".name", "a point spring named '" + name + "' already exists");
  }
  for (const int body : {body_a, body_b})
    if (body < kBase || body >= scene.model.size()) throw SceneInvalid(field, "no such body");
  if (body_a == body_b) throw SceneInvalid(field + ".body_b", "both ends are on one body: it would pull on itself");
  check_non_negative(stiffness, field + ".stiffness");
  check_non_negative(rest_length, field + ".rest_length");
  check_non_negative(damping, field + ".damping");
  node_of_point(scene, body_a, point_a, field + ".point_a");
  node_of_point(scene, body_b, point_b, field + ".point_b");
  std::vector<Pose> poses;
  body_poses(scene.model, scene.q0.data(), poses);
  const auto at = [&](int body, const Vec3& r) { return body == kBase ? r : poses[body].to_base(r); };
  if ((at(body_b, point_b) - at(body_a, point_a)).norm() < 1e-9)
    throw SceneInvalid(field, "its two points coincide at the initial state: the line of the force has no direction");
}

std::shared_ptr<ForceElement> PointSpring::scaled(double L, double M, const Model&) const {
  auto s = std::make_shared<PointSpring>(*this);
  s->point_a *= L;
  s->point_b *= L;
  s->rest_length *= L;
  s->stiffness *= M;  // N/m: (M L / T^2) / L
  s->damping *= M;
  return s;
}

}  // namespace unfurl::sim
