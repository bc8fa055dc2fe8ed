// Typed access to a YAML document's fields for the scene loader: every
// value read is checked (type, range), and every error names the file,
// line, column and field. A node that came from a --set override is named
// by the override instead of a position.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "unfurl/input/input_error.hpp"

namespace unfurl::input {

// "list[i]".
std::string index_field(const std::string& list, std::size_t i);

// Numbers beyond this magnitude are refused: products of a few of them (a
// mass, a gravity, an offset, an inertia) would overflow a double.
inline constexpr double kLargestMagnitude = 1e15;
// The most nodes a document may expand to, aliases counted every time they
// are used: far above any scene (a 1000-stage array is about 1e5), far
// below what an alias bomb (anchors repeating anchors) reaches.
inline constexpr long kMostNodes = 2'000'000;
// The deepest a document may nest: a scene nests five or six levels.
inline constexpr int kDeepestNesting = 100;

class YamlFields {
 public:
  using Keys = std::initializer_list<const char*>;

  explicit YamlFields(std::string source) : source_(std::move(source)) {}

  // Remembers that `node` came from the override `origin` ("--set a.b=1").
  void mark_override(const YAML::Node& node, std::string origin) { overrides_.emplace_back(node, std::move(origin)); }

  // Throws InputError at the node's position.
  [[noreturn]] void fail(const YAML::Node& at, const std::string& field, const std::string& what) const;
  std::string where(const YAML::Node& at) const;
  const std::string& source() const { return source_; }

  // The one YAML document in `text`. Throws InputError with the line for a
  // syntax error, a second document, or a key given twice in one mapping
  // (YAML leaves both to the reader; one would silently win).
  YAML::Node load_document(const std::string& text) const;
  // A --set value's YAML (`origin` names the override in errors), through
  // the same checks: syntax, keys given twice, and the expanded size.
  static YAML::Node load_value(const std::string& text, const std::string& origin);

  void check_keys(const YAML::Node& map, Keys allowed, const std::string& field) const;
  void check_map(const YAML::Node& node, const std::string& field) const;
  YAML::Node require(const YAML::Node& map, const char* key, const std::string& field) const;
  double number(const YAML::Node& node, const std::string& field) const;
  double number_or(const YAML::Node& map, const char* key, double fallback, const std::string& field) const;
  double positive(const YAML::Node& node, const std::string& field) const;
  double non_negative(const YAML::Node& node, const std::string& field) const;
  std::string text(const YAML::Node& node, const std::string& field) const;
  // A body, joint or loop name: letters, digits, '_' and '-', so that it can
  // stand in a CSV header, a --set path and a file name as it is.
  std::string name(const YAML::Node& node, const std::string& field) const;
  // A whole number in [lo, hi].
  long count(const YAML::Node& node, const std::string& field, long lo, long hi) const;
  bool flag(const YAML::Node& node, const std::string& field) const;
  std::vector<double> numbers(const YAML::Node& node, const std::string& field) const;
  Eigen::Vector3d vec3(const YAML::Node& node, const std::string& field) const;
  Eigen::Vector3d vec3_or(const YAML::Node& map, const char* key, const Eigen::Vector3d& fallback,
                          const std::string& field) const;

 private:
  std::string source_;
  std::vector<std::pair<YAML::Node, std::string>> overrides_;  // node, "--set ..."
};

}  // namespace unfurl::input
