#include "unfurl/render/mesh_library.hpp"

#include "gl.hpp"

#include "unfurl/render/mesh_file.hpp"

namespace unfurl::render {

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
  return load(name, find_mesh_file(name, directories_));
}

const MeshModel& MeshLibrary::load(const std::string& name, const std::string& path) {
  auto model = std::make_unique<MeshModel>();
  for (const MeshFilePart& file_part : read_mesh_file(path)) {
    std::vector<float> vertices;  // position, normal
    for (std::size_t v = 0; v < file_part.positions.size(); v += 3) {
      const float* p = &file_part.positions[v];
      const float* n = &file_part.normals[v];
      vertices.insert(vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2]});
      model->bounds.extend(Eigen::Vector3f(p[0], p[1], p[2]));
    }
    MeshPart part;
    part.color = file_part.color;
    part.index_count = static_cast<int>(file_part.indices.size());
    glGenVertexArrays(1, &part.vao);
    glBindVertexArray(part.vao);
    glGenBuffers(1, &part.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, part.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    glGenBuffers(1, &part.ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, part.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(file_part.indices.size() * sizeof(unsigned)),
                 file_part.indices.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    model->parts.push_back(part);
  }
  return *(models_[name] = std::move(model));
}

}  // namespace unfurl::render
