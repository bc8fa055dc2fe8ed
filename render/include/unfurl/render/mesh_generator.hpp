// The project's own meshes, generated as OBJ + MTL: solar panel (cell grid
// on the front, plain back), yoke (a frame of tubes), bus, hinge pin, rod, and the cone that heads a load arrow.
// `unfurl_meshes DIR` writes them; assets/meshes holds the output.
#pragma once

#include <map>
#include <string>

namespace unfurl::render {

// File name -> contents of every built-in mesh file (.obj and .mtl).
std::map<std::string, std::string> builtin_mesh_files();

}  // namespace unfurl::render
