#include "yaml_fields.hpp"

#include <cmath>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl {

namespace {

// Whether `needle` is `haystack` or inside it.
bool contains(const YAML::Node& haystack, const YAML::Node& needle) {
  if (haystack.is(needle)) return true;
  if (haystack.IsSequence() || haystack.IsMap())
    for (const auto& item : haystack)
      if (haystack.IsMap() ? contains(item.first, needle) || contains(item.second, needle)
                           : contains(item, needle))
        return true;
  return false;
}

}  // namespace

std::string index_field(const std::string& list, std::size_t i) {
  return list + "[" + std::to_string(i) + "]";
}

std::string YamlFields::where(const YAML::Node& at) const {
  for (const auto& [node, text] : overrides_)
    if (contains(node, at)) return text;
  const YAML::Mark mark = at.Mark();
  if (mark.is_null()) return source_ + " (with the --set overrides)";
  return source_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

void YamlFields::fail(const YAML::Node& at, const std::string& field, const std::string& what) const {
  throw SceneError(where(at) + ": " + (field.empty() ? "" : field + ": ") + what);
}

void YamlFields::check_map(const YAML::Node& node, const std::string& field) const {
  if (!node.IsMap()) fail(node, field, "expected a mapping of keys to values");
}

void YamlFields::check_keys(const YAML::Node& map, Keys allowed, const std::string& field) const {
  check_map(map, field);
  for (const auto& item : map) {
    const std::string key = item.first.Scalar();
    bool known = false;
    std::string list;
    for (const char* a : allowed) {
      known = known || key == a;
      list += std::string(list.empty() ? "" : ", ") + a;
    }
    if (!known) fail(item.first, field, "unknown key '" + key + "' (expected one of: " + list + ")");
  }
}

YAML::Node YamlFields::require(const YAML::Node& map, const char* key, const std::string& field) const {
  const YAML::Node node = map[key];
  if (!node) fail(map, field, std::string("missing field '") + key + "'");
  return node;
}

double YamlFields::number(const YAML::Node& node, const std::string& field) const {
  if (!node.IsScalar()) fail(node, field, "expected a number");
  double x = 0;
  try {
    x = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(node, field, "expected a number, got '" + node.Scalar() + "'");
  }
  if (!std::isfinite(x)) fail(node, field, "must be a finite number, got '" + node.Scalar() + "'");
  return x;
}

double YamlFields::number_or(const YAML::Node& map, const char* key, double fallback,
                              const std::string& field) const {
  const YAML::Node node = map[key];
  return node ? number(node, field + "." + key) : fallback;
}

double YamlFields::positive(const YAML::Node& node, const std::string& field) const {
  const double x = number(node, field);
  if (!(x > 0)) fail(node, field, "must be positive, got " + node.Scalar());
  return x;
}

double YamlFields::non_negative(const YAML::Node& node, const std::string& field) const {
  const double x = number(node, field);
  if (x < 0) fail(node, field, "must not be negative, got " + node.Scalar());
  return x;
}

std::string YamlFields::text(const YAML::Node& node, const std::string& field) const {
  if (!node.IsScalar()) fail(node, field, "expected a string");
  return node.Scalar();
}

std::vector<double> YamlFields::numbers(const YAML::Node& node, const std::string& field) const {
  if (!node.IsSequence()) fail(node, field, "expected a list of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < node.size(); ++i) out.push_back(number(node[i], index_field(field, i)));
  return out;
}

Vec3 YamlFields::vec3(const YAML::Node& node, const std::string& field) const {
  const std::vector<double> v = numbers(node, field);
  if (v.size() != 3) fail(node, field, "expected 3 numbers, got " + std::to_string(v.size()));
  return Vec3(v[0], v[1], v[2]);
}

Vec3 YamlFields::vec3_or(const YAML::Node& map, const char* key, const Vec3& fallback,
                          const std::string& field) const {
  const YAML::Node node = map[key];
  return node ? vec3(node, field + "." + key) : fallback;
}

bool YamlFields::flag(const YAML::Node& node, const std::string& field) const {
  const std::string value = text(node, field);
  if (value == "true") return true;
  if (value == "false") return false;
  fail(node, field, "expected true or false, got '" + value + "'");
}

}  // namespace unfurl
