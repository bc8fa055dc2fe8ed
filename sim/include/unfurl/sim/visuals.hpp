// What the renderer draws for each body, as a scene file gives it. The
// solver never reads it: the scene loader returns it beside the Scene.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

// What the renderer draws for a body: a mesh from assets/meshes, scaled,
// then turned about an axis, then offset, in the body frame.
struct Visual {
  std::string mesh;
  Vec3 scale = Vec3::Ones();
  Vec3 rotation_axis = Vec3::UnitZ();
  double rotation_deg = 0;
  Vec3 offset = Vec3::Zero();
};

struct SceneVisuals {
  Visual base;
  std::vector<Visual> bodies;  // per body
};

}  // namespace unfurl::sim
