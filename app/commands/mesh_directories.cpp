#include "mesh_directories.hpp"

#include <filesystem>

#include "unfurl/render/mesh_file.hpp"

namespace unfurl::app {

std::vector<std::string> mesh_directories(const sim::Scene& scene) {
  std::vector<std::string> dirs;
  std::error_code ec;
  if (std::filesystem::is_regular_file(scene.source, ec)) {
    const std::filesystem::path here = std::filesystem::path(scene.source).parent_path();
    dirs.push_back(here.empty() ? "." : here.string());
    dirs.push_back((here / ".." / "meshes").string());
  }
  dirs.push_back(render::builtin_mesh_directory());
  return dirs;
}

}  // namespace unfurl::app
