// Helpers shared by the tests.
#pragma once

#include <string>

#include "scene_yaml.hpp"
#include "simulation.hpp"

namespace unfurl::test {

inline std::string asset(const std::string& relative) {
  return std::string(UNFURL_SOURCE_DIR) + "/assets/" + relative;
}

inline Scene scene_file(const std::string& name, const std::vector<Override>& overrides = {}) {
  return load_scene_file(asset("scenes/" + name + ".yaml"), overrides);
}

// Value of coordinate c of the joint named `joint` in a sample.
inline double q_of(const Scene& scene, const Sample& s, const std::string& joint) {
  for (int c = 0; c < scene.model.nq; ++c)
    if (scene.model.joints[scene.model.joint_of_coordinate[c]].name == joint) return s.y[c];
  throw std::runtime_error("no joint " + joint);
}

}  // namespace unfurl::test
