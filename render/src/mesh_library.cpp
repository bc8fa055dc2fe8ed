#include "unfurl/render/mesh_library.hpp"

#include "gl.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>
#include <stdexcept>

namespace unfurl::render {

std::string builtin_mesh_directory() {
  // The source tree's meshes in a build tree, the installed ones otherwise.
  std::error_code ec;
  if (std::filesystem::is_directory(UNFURL_MESH_DIR, ec)) return UNFURL_MESH_DIR;
  return UNFURL_INSTALLED_MESH_DIR;
}

MeshLibrary::MeshLibrary(std::vector<std::string> directories) : directories_(std::move(directories)) {}

MeshLibrary::~MeshLibrary() {
  for (auto& [name, model] : models_)
    for (MeshPart& part : model->parts) {
      glDeleteVertexArrays(1, &part.vao);
      glDeleteBuffers(1, &part.vbo);
      glDeleteBuffers(1, &part.ebo);
    }
}

const MeshModel& MeshLibrary::get(const std::string& name) {
  if (const auto it = models_.find(name); it != models_.end()) return *it->second;
  std::string searched;
  for (const std::string& dir : directories_) {
    for (const char* suffix : {"", ".obj", ".stl", ".gltf", ".glb"}) {
      const std::filesystem::path path = std::filesystem::path(dir) / (name + suffix);
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec)) return load(name, path.string());
    }
    searched += (searched.empty() ? "" : ", ") + dir;
  }
  throw std::runtime_error("mesh '" + name + "' not found (looked in " + searched + ")");
}

const MeshModel& MeshLibrary::load(const std::string& name, const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenNormals |
                                  aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw std::runtime_error(path + ": cannot load the mesh (" + importer.GetErrorString() + ")");
  auto model = std::make_unique<MeshModel>();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    std::vector<float> vertices;  // position, normal
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D p = mesh->mVertices[v];
      const aiVector3D n = mesh->HasNormals() ? mesh->mNormals[v] : aiVector3D(0, 0, 1);
      vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
      model->bounds.extend(Eigen::Vector3f(p.x, p.y, p.z));
    }
    std::vector<unsigned> indices;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        indices.insert(indices.end(), mesh->mFaces[f].mIndices, mesh->mFaces[f].mIndices + 3);

    MeshPart part;
    aiColor4D color;
    const aiMaterial* material = scene->mMaterials[mesh->mMaterialIndex];
    if (aiGetMaterialColor(material, AI_MATKEY_BASE_COLOR, &color) == AI_SUCCESS ||
        aiGetMaterialColor(material, AI_MATKEY_COLOR_DIFFUSE, &color) == AI_SUCCESS)
      part.color = Eigen::Vector3f(color.r, color.g, color.b);
    part.index_count = static_cast<int>(indices.size());
    glGenVertexArrays(1, &part.vao);
    glBindVertexArray(part.vao);
    glGenBuffers(1, &part.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, part.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    glGenBuffers(1, &part.ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, part.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned)),
                 indices.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    model->parts.push_back(part);
  }
  if (model->parts.empty()) throw std::runtime_error(path + ": the mesh has no triangles");
  return *(models_[name] = std::move(model));
}

}  // namespace unfurl::render
