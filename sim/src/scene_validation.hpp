// The checks a scene needs once all of it is read: what no single field can
// say is wrong (a loop that does not close at the initial state, ...).
#pragma once

#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/input/yaml_fields.hpp"

namespace unfurl {

// Throws input::InputError at the loop's entry when a loop's body and image are
// further apart at q0 than the scene's closure_tolerance.
void check_loops_close(const Scene& scene, const std::vector<YAML::Node>& loop_nodes, const input::YamlFields& fields);

}  // namespace unfurl
