// What the renderer draws for each body, and the solid shapes clearance is
// measured between, as a scene file gives them. The solver never reads
// them: the scene loader returns them beside the Scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

// A solid a body's clearance is measured from (a scene's `collision:`):
// a box, sphere or cylinder (its axis along z), or a mesh by name scaled
// along x, y, z; turned about an axis, then offset, in the body frame.
struct CollisionShape {
  enum class Kind { box, sphere, cylinder, mesh };
  Kind kind = Kind::box;
  Vec3 size = Vec3::Zero();  // a box's edge lengths
  double radius = 0;         // a sphere's or a cylinder's
  double length = 0;         // a cylinder's
  std::string mesh;          // a mesh's name
  Vec3 scale = Vec3::Ones();  // a mesh's
  Vec3 rotation_axis = Vec3::UnitZ();
  double rotation_deg = 0;
  Vec3 offset = Vec3::Zero();
};

// What the renderer draws for a body: a mesh from assets/meshes, scaled,
// then turned about an axis, then offset, in the body frame.
struct Visual {
  std::string mesh;
  Vec3 scale = Vec3::Ones();
  Vec3 rotation_axis = Vec3::UnitZ();
  double rotation_deg = 0;
  Vec3 offset = Vec3::Zero();
  // The body's solid for clearance: without a declaration (nullopt) the
  // mesh as drawn; an empty list (`collision: none`) leaves the body out.
  std::optional<std::vector<CollisionShape>> collision;
};

struct SceneVisuals {
  Visual base;
  std::vector<Visual> bodies;  // per body
};

}  // namespace unfurl::sim
