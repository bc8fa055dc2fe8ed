#include "unfurl/sim/elements/point_frame.hpp"

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

PointFrame point_frame(const ElementState& s, int body, const Vec3& point) {
  PointFrame at;
  at.body = body;
  if (body == kBase) {
    at.v = s.base_velocity;
    at.r = point;
    return at;
  }
  // A flexible body's root is held to its frame: a point there rides on
  // the frame, as on a rigid body.
  at.node = s.model.flexible(body) ? s.model.bodies[body].flexible->node_of(point) : -1;
  if (at.node < 0) {
    at.pose = s.poses[body];
    at.v = s.v[body];
    at.r = point;
    return at;
  }
  const flexible::FlexibleBody& f = *s.model.bodies[body].flexible;
  at.pose = s.poses[body].child(s.sweep->node_placement(body, at.node));
  at.v = s.sweep->node_frame_velocity(body, at.node, s.v, s.w.data());
  at.r = point - f.nodes[at.node].point;
  return at;
}

void add_frame_wrench(const ElementState& s, int body, int node, const Vec6& wrench, ElementForces& out) {
  if (body == kBase) return;
  if (node < 0) {
    out.F[body] += wrench;
    return;
  }
  const flexible::ExtendedVector hat = s.sweep->node_force(body, node, wrench);
  out.F[body] += hat.head<6>();
  const VelocityIndex e{s.model.first_elastic_velocity[body]};
  for (int k = 0; k + 6 < hat.size(); ++k) out.Q[e + k] += hat[6 + k];
}

void add_point_force(const ElementState& s, const PointFrame& at, const Vec3& f_base, ElementForces& out) {
  if (at.body == kBase) return;
  const Vec3 f = at.pose.rotation * f_base;
  Vec6 wrench;
  wrench << f, at.r.cross(f);
  add_frame_wrench(s, at.body, at.node, wrench, out);
}

void add_point_wrench(const ElementState& s, const PointFrame& at, const Vec3& f_base, const Vec3& m_base,
                      ElementForces& out) {
  if (at.body == kBase) return;
  const Mat3& R = at.pose.rotation;
  const Vec3 f = R * f_base;
  Vec6 wrench;
  wrench << f, R * m_base + at.r.cross(f);
  add_frame_wrench(s, at.body, at.node, wrench, out);
}

int node_of_point(const Scene& scene, int body, const Vec3& point, const std::string& field) {
  if (body < 0 || body >= scene.model.size() || !scene.model.flexible(body)) return -1;
  const flexible::FlexibleBody& f = *scene.model.bodies[body].flexible;
  const int a = f.node_of(point);
  if (a < 0 && !f.on_frame(point))
    throw SceneInvalid(field, "no node of the flexible body '" + scene.model.bodies[body].name +
                                  "' is at this point: an element's point on a flexible body rides on its frame or "
                                  "is one of its attachment points (BeamBodySpec::attachments, "
                                  "PlateBodySpec::attachments; a scene file's reader makes every such point one)");
  return a;
}

}  // namespace unfurl::sim
