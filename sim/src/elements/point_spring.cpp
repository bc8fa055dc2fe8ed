#include "unfurl/sim/elements/point_spring.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

namespace {

struct PointMotion {
  Vec3 x, x_dot;  // base frame
};

PointMotion point_motion(int body, const Vec3& r, const std::vector<Pose>& poses, const std::vector<Vec6>& v,
                         const Vec6& v_base) {
  if (body == kBase) return {r, v_base.head<3>() + v_base.tail<3>().cross(r)};
  const Pose& P = poses[body];
  const Vec6& vi = v[body];
  return {P.to_base(r), P.rotation.transpose() * (vi.head<3>() + vi.tail<3>().cross(r))};
}

void add_pull(int body, const Vec3& r, const Vec3& f_base, const std::vector<Pose>& poses, std::vector<Vec6>& F) {
  if (body == kBase) return;
  const Vec3 f = poses[body].rotation * f_base;
  F[body].head<3>() += f;
  F[body].tail<3>() += r.cross(f);
}

}  // namespace

PointSpringGeometry PointSpring::geometry(const std::vector<Pose>& poses, const std::vector<Vec6>& v,
                                          const Vec6& v_base) const {
  const PointMotion a = point_motion(body_a, point_a, poses, v, v_base);
  const PointMotion b = point_motion(body_b, point_b, poses, v, v_base);
  PointSpringGeometry g;
  g.a = a.x;
  g.b = b.x;
  const Vec3 d = b.x - a.x;
  g.length = d.norm();
  if (g.length > 1e-12) g.direction = d / g.length;
  g.rate = g.direction.dot(b.x_dot - a.x_dot);
  return g;
}

void PointSpring::add_forces(const ElementState& s, ElementForces& out) const {
  const PointSpringGeometry g = geometry(s.poses, s.v, s.base_velocity);
  const double T = tension(g.length, g.rate);
  add_pull(body_a, point_a, T * g.direction, s.poses, out.F);
  add_pull(body_b, point_b, -T * g.direction, s.poses, out.F);
}

double PointSpring::potential_energy(const ElementState& s) const {
  return energy(geometry(s.poses, s.v, s.base_velocity).length);
}

double PointSpring::dissipated_power(const ElementState& s) const {
  const PointSpringGeometry g = geometry(s.poses, s.v, s.base_velocity);
  return (tension(g.length, g.rate) - elastic(g.length)) * g.rate;
}

std::vector<LoadColumn> PointSpring::load_columns(const Model&) const { return {{"tension." + name, "N", "", -1}}; }

void PointSpring::load_values(const ElementState& s, double* values) const {
  const PointSpringGeometry g = geometry(s.poses, s.v, s.base_velocity);
  values[0] = tension(g.length, g.rate);
}

std::vector<ElementParameter> PointSpring::parameters() const {
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
