// Where a scene's meshes are looked up, for pictures and for clearance.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"

namespace unfurl::app {

// Beside the scene file, in ../meshes from it, then the built-in
// assets/meshes.
std::vector<std::string> mesh_directories(const sim::Scene& scene);

}  // namespace unfurl::app
