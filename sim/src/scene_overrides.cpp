#include "scene_overrides.hpp"

#include <sstream>

namespace unfurl {

// Follows a dotted path; list elements by index or by name/joint/body.
void apply_override(YAML::Node& root, const Override& o, YamlFields& fields) {
  const std::string origin = "--set " + o.path + "=" + o.value;
  std::vector<std::string> parts;
  std::stringstream ss(o.path);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  if (parts.empty() || o.path.empty()) throw SceneError(origin + ": empty path");
  YAML::Node value;
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw SceneError(origin + ": the value is not valid YAML: " + e.msg);
  }
  YAML::Node cur;
  cur.reset(root);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    const bool last = k + 1 == parts.size();
    if (cur.IsSequence()) {
      std::size_t index = cur.size();
      const bool numeric = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
      for (std::size_t i = 0; i < cur.size(); ++i) {
        const YAML::Node item = cur[i];
        if (numeric ? part == std::to_string(i)
                    : item.IsMap() && ((item["name"] && item["name"].Scalar() == part) ||
                                       (item["joint"] && item["joint"].Scalar() == part) ||
                                       (item["body"] && item["body"].Scalar() == part))) {
          index = i;
          break;
        }
      }
      if (index == cur.size())
        throw SceneError(origin + ": no element '" + part + "' in the list (it has " + std::to_string(cur.size()) +
                         (numeric ? ", numbered from 0)" : "; give an index or a name)"));
      if (last) {
        cur[index] = value;
      } else {
        YAML::Node next = cur[index];
        cur.reset(next);
      }
    } else if (cur.IsMap() || cur.IsNull()) {
      if (last) {
        cur[part] = value;
      } else {
        if (!cur[part]) cur[part] = YAML::Node(YAML::NodeType::Map);
        YAML::Node next = cur[part];
        cur.reset(next);
      }
    } else {
      throw SceneError(origin + ": '" + part + "' is inside a value, not a mapping or list");
    }
  }
  fields.mark_override(value, origin);
}

Override parse_override(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + assignment + ": expected KEY=VALUE, for example springs.0.stiffness=0.2");
  return {assignment.substr(0, eq), assignment.substr(eq + 1)};
}

}  // namespace unfurl
