// Mesh files (OBJ, STL, glTF) read with assimp into plain arrays, without
// GL: the mesh library uploads them, clearance measures from them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace unfurl::render {

// One material's triangles: positions and normals (x, y, z each), three
// indices per triangle, and the material's diffuse colour.
struct MeshFilePart {
  std::vector<float> positions, normals;
  std::vector<unsigned> indices;
  Eigen::Vector3f color{0.7f, 0.7f, 0.7f};
};

// The path of mesh `name` in the first of `directories` that has it, as
// NAME, NAME.obj, NAME.stl, NAME.gltf or NAME.glb. Throws
// std::runtime_error naming the mesh and the directories searched.
std::string find_mesh_file(const std::string& name, const std::vector<std::string>& directories);

// Throws std::runtime_error naming the file when it cannot be read or has
// no triangles.
std::vector<MeshFilePart> read_mesh_file(const std::string& path);

// The built-in meshes: the source tree's assets/meshes in a build tree, the
// installed ones otherwise.
std::string builtin_mesh_directory();

}  // namespace unfurl::render
