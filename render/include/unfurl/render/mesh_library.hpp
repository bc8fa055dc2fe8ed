// Meshes by name, loaded with assimp (OBJ, STL, glTF) on first use and kept
// on the GPU: one part per material, each with its diffuse colour.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>
#include <vector>


namespace unfurl::render {

struct MeshPart {
  unsigned vao = 0, vbo = 0, ebo = 0;
  int index_count = 0;
  Eigen::Vector3f color{0.7f, 0.7f, 0.7f};
};

struct MeshModel {
  std::vector<MeshPart> parts;
  Eigen::AlignedBox3f bounds;  // in the mesh's own units
};

class MeshLibrary {
 public:
  // Meshes are looked up in these directories, in order, as NAME, NAME.obj,
  // NAME.stl, NAME.gltf or NAME.glb.
  explicit MeshLibrary(std::vector<std::string> directories);
  ~MeshLibrary();
  MeshLibrary(const MeshLibrary&) = delete;
  MeshLibrary& operator=(const MeshLibrary&) = delete;

  // Throws std::runtime_error naming the mesh and the directories searched.
  const MeshModel& get(const std::string& name);

 private:
  const MeshModel& load(const std::string& name, const std::string& path);

  std::vector<std::string> directories_;
  std::map<std::string, std::unique_ptr<MeshModel>> models_;
};

}  // namespace unfurl::render
