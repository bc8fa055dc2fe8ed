#include "unfurl/input/yaml_fields.hpp"

#include <cmath>
#include <set>
#include <sstream>

namespace unfurl::input {

namespace {

// Whether `needle` is `haystack` or inside it.
bool contains(const YAML::Node& haystack, const YAML::Node& needle) {
  if (haystack.is(needle)) return true;
  if (haystack.IsSequence() || haystack.IsMap())
    for (const auto& item : haystack)
      if (haystack.IsMap() ? contains(item.first, needle) || contains(item.second, needle) : contains(item, needle))
        return true;
  return false;
}

// Counts the nodes `node` expands to, each alias as many times as it is
// used, and stops at kMostNodes: a document of nested aliases (an alias
// bomb) is refused before anything walks it whole. Stops as well below
// kDeepestNesting levels, where an anchor used inside itself (a cycle) or
// a deep nest would overflow the stack of whatever walks it next.
enum class Extent { fits, too_many, too_deep };

Extent count_nodes(const YAML::Node& node, long& count, int depth) {
  if (++count > kMostNodes) return Extent::too_many;
  if (depth > kDeepestNesting) return Extent::too_deep;
  if (node.IsSequence())
    for (const YAML::Node& item : node)
      if (const Extent e = count_nodes(item, count, depth + 1); e != Extent::fits) return e;
  if (node.IsMap())
    for (const auto& item : node)
      for (const YAML::Node& part : {item.first, item.second})
        if (const Extent e = count_nodes(part, count, depth + 1); e != Extent::fits) return e;
  return Extent::fits;
}

void check_size(const YAML::Node& node, const std::string& source) {
  long count = 0;
  switch (count_nodes(node, count, 0)) {
    case Extent::fits:
      return;
    case Extent::too_many:
      throw InputError(source + ": the YAML expands to more than " + std::to_string(kMostNodes) +
                       " values (anchors repeated through aliases); refused");
    case Extent::too_deep:
      throw InputError(source + ": the YAML nests deeper than " + std::to_string(kDeepestNesting) +
                       " levels (or an anchor is used inside itself); refused");
  }
}

void check_unique_keys(const YAML::Node& node, const YamlFields& fields) {
  if (node.IsSequence())
    for (const YAML::Node& item : node) check_unique_keys(item, fields);
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& item : node) {
    if (item.first.IsScalar() && !seen.insert(item.first.Scalar()).second)
      fields.fail(item.first, "", "the key '" + item.first.Scalar() + "' is given twice in one mapping");
    check_unique_keys(item.second, fields);
  }
}

// A document marker at the start of a line ("---" or "...", then a space or
// the line's end) after some content starts a second document. Found on the
// text because yaml-cpp 0.7's LoadAll never returns on some inputs (",0").
// (Inside a block scalar such a line would be indented; in a quoted scalar
// YAML forbids it.)
void check_single_document(const std::string& text, const std::string& source) {
  std::istringstream lines(text);
  bool content = false, ended = false;
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const bool start = line.rfind("---", 0) == 0, end = line.rfind("...", 0) == 0;
    const bool marker = (start || end) && (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r');
    const auto first = line.find_first_not_of(" \t\r");
    const bool blank = first == std::string::npos || line[first] == '#';
    if ((marker && start && content) || (!marker && !blank && ended))
      throw InputError(source + ":" + std::to_string(number) +
                       ":1: a second YAML document; a scene file holds one (remove the '---' line or split the file)");
    if (marker && end) ended = content;
    if (!marker && !blank && line[first] != '%') content = true;
  }
}

}  // namespace

std::string index_field(const std::string& list, std::size_t i) { return list + "[" + std::to_string(i) + "]"; }

std::string YamlFields::where(const YAML::Node& at) const {
  for (const auto& [node, text] : overrides_)
    if (contains(node, at)) return text;
  const YAML::Mark mark = at.Mark();
  if (mark.is_null()) return source_ + " (with the --set overrides)";
  return source_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

void YamlFields::fail(const YAML::Node& at, const std::string& field, const std::string& what) const {
  throw InputError(where(at) + ": " + (field.empty() ? "" : field + ": ") + what);
}

YAML::Node YamlFields::load_document(const std::string& text) const {
  check_single_document(text, source_);
  YAML::Node document;
  try {
    document = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(source_ + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                     ": YAML syntax error: " + e.msg);
  }
  if (!document || document.IsNull()) throw InputError(source_ + ": the scene file is empty or holds no YAML mapping");
  check_size(document, source_);
  check_unique_keys(document, *this);
  return document;
}

YAML::Node YamlFields::load_value(const std::string& text, const std::string& origin) {
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(origin + ": the value is not valid YAML: " + e.msg);
  }
  check_size(value, origin);
  check_unique_keys(value, YamlFields(origin));
  return value;
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
  if (std::abs(x) > kLargestMagnitude)
    fail(node, field, node.Scalar() + " is beyond +-1e15, where products of the scene's values overflow");
  return x;
}

long YamlFields::count(const YAML::Node& node, const std::string& field, long lo, long hi) const {
  const double x = number(node, field);
  if (x != std::floor(x) || x < static_cast<double>(lo) || x > static_cast<double>(hi))
    fail(node, field,
         "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + node.Scalar());
  return static_cast<long>(x);
}

double YamlFields::number_or(const YAML::Node& map, const char* key, double fallback, const std::string& field) const {
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

std::string YamlFields::name(const YAML::Node& node, const std::string& field) const {
  const std::string n = text(node, field);
  if (n.empty() || n.size() > 64 ||
      n.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
    fail(node, field,
         "the name '" + n + "' has characters other than letters, digits, '_' and '-' (or is empty or over 64)");
  return n;
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

Eigen::Vector3d YamlFields::vec3(const YAML::Node& node, const std::string& field) const {
  const std::vector<double> v = numbers(node, field);
  if (v.size() != 3) fail(node, field, "expected 3 numbers, got " + std::to_string(v.size()));
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Vector3d YamlFields::vec3_or(const YAML::Node& map, const char* key, const Eigen::Vector3d& fallback,
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

}  // namespace unfurl::input
