#include "unfurl/studies/body_solids.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

namespace unfurl::studies {

namespace {

sim::Mat3 turn(const sim::Vec3& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180, axis).toRotationMatrix();
}

Solid mesh_solid(const Triangles& mesh, const sim::Vec3& scale, const sim::Vec3& axis, double degrees,
                 const sim::Vec3& offset) {
  Solid s;
  s.kind = sim::CollisionShape::Kind::mesh;
  s.mesh = mesh;
  for (sim::Vec3& v : s.mesh.vertices) v = v.cwiseProduct(scale);
  s.rotation = turn(axis, degrees);
  s.offset = offset;
  return s;
}

// The solids of one body's visual; a mesh that cannot be had is named.
std::vector<Solid> solids_of(const sim::Visual& v, const std::string& body, const MeshReader& read_mesh,
                             std::vector<std::string>* unread) {
  std::vector<Solid> out;
  const auto mesh = [&](const std::string& name) -> std::optional<Triangles> {
    std::string why = kNoMeshReader;
    if (read_mesh) try {
        return read_mesh(name);
      } catch (const std::exception& e) {
        why = e.what();
      }
    if (unread) unread->push_back(body + " (mesh " + name + ": " + why + ")");
    return std::nullopt;
  };
  if (!v.collision) {
    if (v.mesh.empty()) return out;
    if (const auto m = mesh(v.mesh)) out.push_back(mesh_solid(*m, v.scale, v.rotation_axis, v.rotation_deg, v.offset));
    return out;
  }
  for (const sim::CollisionShape& c : *v.collision) {
    if (c.kind == sim::CollisionShape::Kind::mesh) {
      if (const auto m = mesh(c.mesh)) out.push_back(mesh_solid(*m, c.scale, c.rotation_axis, c.rotation_deg, c.offset));
      continue;
    }
    Solid s;
    s.kind = c.kind;
    s.size = c.size;
    s.radius = c.radius;
    s.length = c.length;
    s.rotation = turn(c.rotation_axis, c.rotation_deg);
    s.offset = c.offset;
    out.push_back(s);
  }
  return out;
}

}  // namespace

double Solid::reach() const {
  using Kind = sim::CollisionShape::Kind;
  double own = 0;  // about the solid's own origin
  switch (kind) {
    case Kind::box: own = 0.5 * size.norm(); break;
    case Kind::sphere: own = radius; break;
    case Kind::cylinder: own = std::hypot(radius, 0.5 * length); break;
    case Kind::mesh:
      double far = 0;
      for (const sim::Vec3& v : mesh.vertices) far = std::max(far, (offset + rotation * v).norm());
      return far;
  }
  return offset.norm() + own;
}

BodySolids body_solids(const sim::Scene& scene, const sim::SceneVisuals& visuals, const MeshReader& read_mesh,
                       std::vector<std::string>* unread) {
  const sim::Model& m = scene.model;
  std::set<int> images;
  for (const sim::Loop& loop : scene.loops) images.insert(loop.image);
  BodySolids out;
  if (!m.free_floating()) out.base = solids_of(visuals.base, m.base_name, read_mesh, unread);
  out.bodies.resize(m.size());
  for (int i = 0; i < m.size(); ++i)
    if (!images.count(i) && i < static_cast<int>(visuals.bodies.size()))
      out.bodies[i] = solids_of(visuals.bodies[i], m.bodies[i].name, read_mesh, unread);
  return out;
}

}  // namespace unfurl::studies
