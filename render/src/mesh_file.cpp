#include "unfurl/render/mesh_file.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>
#include <stdexcept>

namespace unfurl::render {

std::string find_mesh_file(const std::string& name, const std::vector<std::string>& directories) {
  std::string searched;
  for (const std::string& dir : directories) {
    for (const char* suffix : {"", ".obj", ".stl", ".gltf", ".glb"}) {
      const std::filesystem::path path = std::filesystem::path(dir) / (name + suffix);
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec)) return path.string();
    }
    searched += (searched.empty() ? "" : ", ") + dir;
  }
  throw std::runtime_error("mesh '" + name + "' not found (looked in " + searched + ")");
}

std::vector<MeshFilePart> read_mesh_file(const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenNormals |
                                  aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw std::runtime_error(path + ": cannot load the mesh (" + importer.GetErrorString() + ")");
  std::vector<MeshFilePart> parts;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    MeshFilePart part;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D p = mesh->mVertices[v];
      const aiVector3D n = mesh->HasNormals() ? mesh->mNormals[v] : aiVector3D(0, 0, 1);
      part.positions.insert(part.positions.end(), {p.x, p.y, p.z});
      part.normals.insert(part.normals.end(), {n.x, n.y, n.z});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        part.indices.insert(part.indices.end(), mesh->mFaces[f].mIndices, mesh->mFaces[f].mIndices + 3);
    aiColor4D color;
    const aiMaterial* material = scene->mMaterials[mesh->mMaterialIndex];
    if (aiGetMaterialColor(material, AI_MATKEY_BASE_COLOR, &color) == AI_SUCCESS ||
        aiGetMaterialColor(material, AI_MATKEY_COLOR_DIFFUSE, &color) == AI_SUCCESS)
      part.color = Eigen::Vector3f(color.r, color.g, color.b);
    parts.push_back(std::move(part));
  }
  if (parts.empty()) throw std::runtime_error(path + ": the mesh has no triangles");
  return parts;
}

std::string builtin_mesh_directory() {
  std::error_code ec;
  if (std::filesystem::is_directory(UNFURL_MESH_DIR, ec)) return UNFURL_MESH_DIR;
  return UNFURL_INSTALLED_MESH_DIR;
}

}  // namespace unfurl::render
