// The solids clearance is measured between, per body, in the body's frame:
// a scene's declared collision shapes, or the meshes it draws. Meshes come
// as triangles from whoever reads mesh files (the renderer's reader, for
// the application); this layer reads no files.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/visuals.hpp"

namespace unfurl::studies {

struct Triangles {
  std::vector<sim::Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
};

// One solid of a body: a primitive, or triangles, placed in the body frame.
struct Solid {
  sim::CollisionShape::Kind kind = sim::CollisionShape::Kind::mesh;
  sim::Vec3 size = sim::Vec3::Zero();  // a box's edges
  double radius = 0, length = 0;       // a sphere's, a cylinder's (along z)
  Triangles mesh;                      // scaled, in the solid's frame
  sim::Mat3 rotation = sim::Mat3::Identity();  // solid frame -> body frame
  sim::Vec3 offset = sim::Vec3::Zero();
  // The farthest any of its points is from the body's origin.
  double reach() const;
};

struct BodySolids {
  std::vector<Solid> base;
  std::vector<std::vector<Solid>> bodies;  // per body
};

// A mesh's triangles by name, in the mesh's own units; throws
// std::runtime_error when it cannot be read.
using MeshReader = std::function<Triangles(const std::string& name)>;

// Why a mesh was not read when there is no reader (`unread` says it).
inline constexpr const char* kNoMeshReader = "no mesh reader in this build";

// The solids of each body: its `collision:` shapes where declared, else its
// mesh as drawn (scale, rotation, offset), else none. A loop's image is the
// split body's other half: it has no solid of its own. Without a reader
// (nullptr), a body that needs a mesh gets none and is named in `unread`.
BodySolids body_solids(const sim::Scene& scene, const sim::SceneVisuals& visuals, const MeshReader& read_mesh,
                       std::vector<std::string>* unread = nullptr);

}  // namespace unfurl::studies
