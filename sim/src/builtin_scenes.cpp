#include <map>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::sim {

const std::map<std::string, std::string>& builtin_scene_texts();  // generated

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : builtin_scene_texts()) names.push_back(name);
  return names;
}

const std::string& builtin_scene_text(const std::string& name) {
  const auto& texts = builtin_scene_texts();
  const auto it = texts.find(name);
  if (it == texts.end()) {
    std::string known;
    for (const auto& [n, text] : texts) known += (known.empty() ? "" : ", ") + n;
    throw input::InputError("no built-in scene '" + name + "' (built in: " + known + ")");
  }
  return it->second;
}

SceneFile read_builtin_scene(const std::string& name, const std::vector<Override>& overrides) {
  return read_scene_text(builtin_scene_text(name), "built-in:" + name, overrides);
}

Scene load_builtin_scene(const std::string& name, const std::vector<Override>& overrides) {
  return read_builtin_scene(name, overrides).scene;
}

}  // namespace unfurl::sim
