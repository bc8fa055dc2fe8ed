#include "unfurl/sim/point_spring.hpp"

namespace unfurl {

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

PointSpringGeometry point_spring_geometry(const PointSpring& s, const std::vector<Pose>& poses,
                                          const std::vector<Vec6>& v, const Vec6& v_base) {
  const PointMotion a = point_motion(s.body_a, s.point_a, poses, v, v_base);
  const PointMotion b = point_motion(s.body_b, s.point_b, poses, v, v_base);
  PointSpringGeometry g;
  g.a = a.x;
  g.b = b.x;
  const Vec3 d = b.x - a.x;
  g.length = d.norm();
  if (g.length > 1e-12) g.direction = d / g.length;
  g.rate = g.direction.dot(b.x_dot - a.x_dot);
  return g;
}

void add_point_spring_force(const PointSpring& s, const PointSpringGeometry& g, double tension,
                            const std::vector<Pose>& poses, std::vector<Vec6>& F) {
  add_pull(s.body_a, s.point_a, tension * g.direction, poses, F);
  add_pull(s.body_b, s.point_b, -tension * g.direction, poses, F);
}

}  // namespace unfurl
