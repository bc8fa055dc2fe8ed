#include "scene_clearance.hpp"

#include <map>
#include <memory>
#include <utility>

#include "unfurl/studies/clearance.hpp"
#ifdef UNFURL_WITH_RENDER
#include "mesh_directories.hpp"
#include "unfurl/render/mesh_file.hpp"
#endif

namespace unfurl::app {

namespace {

#ifdef UNFURL_WITH_RENDER
// A mesh's triangles, all its materials' together, each file read once.
studies::MeshReader mesh_reader(const sim::Scene& scene) {
  auto cache = std::make_shared<std::map<std::string, studies::Triangles>>();
  return [cache, directories = mesh_directories(scene)](const std::string& name) {
    if (const auto it = cache->find(name); it != cache->end()) return it->second;
    studies::Triangles mesh;
    for (const render::MeshFilePart& part : render::read_mesh_file(render::find_mesh_file(name, directories))) {
      const int first = static_cast<int>(mesh.vertices.size());
      for (std::size_t v = 0; v < part.positions.size(); v += 3)
        mesh.vertices.emplace_back(part.positions[v], part.positions[v + 1], part.positions[v + 2]);
      for (std::size_t f = 0; f + 2 < part.indices.size(); f += 3)
        mesh.faces.push_back({first + static_cast<int>(part.indices[f]), first + static_cast<int>(part.indices[f + 1]),
                              first + static_cast<int>(part.indices[f + 2])});
    }
    return (*cache)[name] = mesh;
  };
}
#else
studies::MeshReader mesh_reader(const sim::Scene&) { return nullptr; }
#endif

}  // namespace

studies::BodySolids scene_solids(const sim::Scene& scene, const sim::SceneVisuals& visuals,
                                 std::vector<std::string>* unread) {
  return studies::body_solids(scene, visuals, mesh_reader(scene), unread);
}

sim::Clearance run_clearance(const sim::Scene& scene, const studies::BodySolids& solids,
                             std::vector<std::string> unread, const sim::Trajectory& trajectory,
                             const std::atomic<bool>* cancel) {
  sim::Clearance c = studies::check_clearance(scene, solids, trajectory, cancel);
  c.unread = std::move(unread);
  return c;
}

sim::Clearance run_clearance(const sim::Scene& scene, const sim::SceneVisuals& visuals,
                             const sim::Trajectory& trajectory, const std::atomic<bool>* cancel) {
  std::vector<std::string> unread;
  const studies::BodySolids solids = scene_solids(scene, visuals, &unread);
  return run_clearance(scene, solids, std::move(unread), trajectory, cancel);
}

}  // namespace unfurl::app
