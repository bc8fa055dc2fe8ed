#include "scene_overrides.hpp"

#include <sstream>

namespace unfurl::sim {

namespace {

std::vector<std::string> path_parts(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  return parts;
}

bool is_index(const std::string& part) {
  return !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
}

// What a list element is called in a path: its name, joint or body.
std::string element_name(const YAML::Node& item) {
  if (!item.IsMap()) return "";
  for (const char* key : {"name", "joint", "body"})
    if (item[key] && item[key].IsScalar()) return item[key].Scalar();
  return "";
}

bool element_is_called(const YAML::Node& item, const std::string& part) {
  if (!item.IsMap()) return false;
  for (const char* key : {"name", "joint", "body"})
    if (item[key] && item[key].IsScalar() && item[key].Scalar() == part) return true;
  return false;
}

// The index of the element `part` names in `list` (its index, or its name,
// joint or body), or list.size().
std::size_t element_index(const YAML::Node& list, const std::string& part) {
  for (std::size_t i = 0; i < list.size(); ++i)
    if (is_index(part) ? part == std::to_string(i) : element_is_called(list[i], part)) return i;
  return list.size();
}

YAML::Node load_scene_document(const std::string& text, const std::string& source) {
  return input::YamlFields(source).load_document(text);
}

void expand(const YAML::Node& node, const std::vector<std::string>& parts, std::size_t k, const std::string& prefix,
            std::vector<std::string>& out) {
  if (k == parts.size()) {
    out.push_back(prefix);
    return;
  }
  const std::string join = prefix.empty() ? "" : prefix + ".";
  if (parts[k] == "*") {
    if (!node.IsSequence()) return;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string name = element_name(node[i]);
      expand(node[i], parts, k + 1, join + (name.empty() ? std::to_string(i) : name), out);
    }
  } else if (node.IsSequence()) {
    const std::size_t i = element_index(node, parts[k]);
    if (i < node.size()) expand(node[i], parts, k + 1, join + parts[k], out);
  } else if (node.IsMap() && node[parts[k]]) {
    expand(node[parts[k]], parts, k + 1, join + parts[k], out);
  }
}

}  // namespace

std::vector<std::string> expand_scene_path(const std::string& text, const std::string& source,
                                           const std::string& path) {
  std::vector<std::string> out;
  expand(load_scene_document(text, source), path_parts(path), 0, "", out);
  if (out.empty()) throw input::InputError(source + ": no value at " + path);
  return out;
}

double scene_number(const std::string& text, const std::string& source, const std::string& path) {
  YAML::Node cur = load_scene_document(text, source);
  for (const std::string& part : path_parts(path)) {
    YAML::Node next;
    if (cur.IsSequence()) {
      const std::size_t i = element_index(cur, part);
      if (i < cur.size()) next = cur[i];
    } else if (cur.IsMap()) {
      next = cur[part];
    }
    if (!next) throw input::InputError(source + ": no value at " + path);
    cur.reset(next);
  }
  double x = 0;
  if (!cur.IsScalar() || !YAML::convert<double>::decode(cur, x))
    throw input::InputError(source + ": the value at " + path + " is not a number");
  return x;
}

// Follows a dotted path; list elements by index or by name/joint/body.
void apply_override(YAML::Node& root, const Override& o, input::YamlFields& fields) {
  const std::string origin = "--set " + o.path + "=" + o.value;
  const std::vector<std::string> parts = path_parts(o.path);
  if (parts.empty() || o.path.empty()) throw input::InputError(origin + ": empty path");
  const YAML::Node value = input::YamlFields::load_value(o.value, origin);
  YAML::Node cur;
  cur.reset(root);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    const bool last = k + 1 == parts.size();
    if (cur.IsSequence()) {
      const std::size_t index = element_index(cur, part);
      const bool numeric = is_index(part);
      if (index == cur.size())
        throw input::InputError(origin + ": no element '" + part + "' in the list (it has " +
                                std::to_string(cur.size()) +
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
      throw input::InputError(origin + ": '" + part + "' is inside a value, not a mapping or list");
    }
  }
  fields.mark_override(value, origin);
}

std::string scene_text_with(const std::string& text, const std::string& source, const std::vector<Override>& overrides) {
  input::YamlFields fields(source);
  YAML::Node root = fields.load_document(text);
  for (const Override& o : overrides) apply_override(root, o, fields);
  YAML::Emitter out;
  out << root;
  std::string header = "# Saved by unfurl from " + source + " with these changes:\n";
  for (const Override& o : overrides) header += "#   " + o.path + " = " + o.value + "\n";
  header += "# (yaml-cpp does not keep the original's comments.)\n";
  return header + out.c_str() + "\n";
}

Override parse_override(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw input::InputError("--set " + assignment + ": expected KEY=VALUE, for example springs.0.stiffness=0.2");
  return {assignment.substr(0, eq), assignment.substr(eq + 1)};
}

}  // namespace unfurl::sim
