// The --set overrides of a scene: a dotted path into the YAML document,
// list elements chosen by index or by their name (or joint, or body).
#pragma once

#include <yaml-cpp/yaml.h>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/input/yaml_fields.hpp"

namespace unfurl::sim {

// Sets the value at the override's path in root (creating mappings on the
// way), and tells `fields` where the new node came from. Throws input::InputError
// naming the override.
void apply_override(YAML::Node& root, const Override& o, input::YamlFields& fields);

}  // namespace unfurl::sim
