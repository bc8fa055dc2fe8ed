#include "scene_validation.hpp"

#include <sstream>

#include "unfurl/sim/kinematics.hpp"

namespace unfurl {

void check_loops_close(const Scene& scene, const std::vector<YAML::Node>& loop_nodes, const input::YamlFields& fields) {
  std::vector<Pose> poses;
  body_poses(scene.model, scene.q0.data(), poses);
  for (std::size_t l = 0; l < scene.loops.size(); ++l) {
    const Loop& loop = scene.loops[l];
    const ClosureError e = closure_error(poses[loop.body], poses[loop.image]);
    if (e.distance > scene.closure_tolerance || e.angle > scene.closure_tolerance) {
      std::ostringstream s;
      s.precision(6);
      s << "loop '" << loop.name << "' does not close at the initial state: the origins of '"
        << scene.model.bodies[loop.body].name << "' and '" << scene.model.bodies[loop.image].name << "' are "
        << e.distance << " m apart and their frames " << e.angle << " rad apart (closure_tolerance "
        << scene.closure_tolerance << ")";
      fields.fail(loop_nodes[l], input::index_field("loops", l), s.str());
    }
  }
}

}  // namespace unfurl
