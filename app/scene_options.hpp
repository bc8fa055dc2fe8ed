// The options every command shares: which scene (a file or a built-in
// name, the pantograph by default), --set overrides and the run settings
// flags (--t-end, --integrator, --rtol, --atol, --dt, --sample).
#pragma once

#include <optional>
#include <set>
#include <string>

#include "cli.hpp"
#include "scene.hpp"

namespace unfurl::app {

// Flags that take a value, for Args.
const std::set<std::string>& scene_flags();
// The help text of those flags.
const char* scene_flags_help();

// Loads the scene named by `argument` (a path, or a built-in scene name) with
// the --set overrides of `args`, then applies the run flags. Throws
// SceneError (exit 2) or UsageError.
Scene load_scene(const std::optional<std::string>& argument, const Args& args);

}  // namespace unfurl::app
