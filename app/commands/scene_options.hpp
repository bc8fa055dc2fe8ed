// The options every command shares: which scene (a file or a built-in
// name, the pantograph by default), --set overrides and the run settings
// flags (--t-end, --integrator, --rtol, --atol, --dt, --sample).
#pragma once

#include <optional>
#include <set>
#include <string>

#include "cli.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace unfurl::app {

// Flags that take a value, for Args.
const std::set<std::string>& scene_flags();
// The help text of those flags.
const char* scene_flags_help();

// The overrides the flags ask for: every --set, then the run flags.
std::vector<sim::Override> overrides_from(const Args& args);

// Reads the scene named by `argument` (a path, or a built-in scene name)
// with the --set overrides of `args`, then applies the run flags: the Scene
// and its visuals. Throws input::InputError (exit 2) or UsageError.
sim::SceneFile read_scene(const std::optional<std::string>& argument, const Args& args);
// The Scene alone.
sim::Scene load_scene(const std::optional<std::string>& argument, const Args& args);

// The scene named `name` (a path, or a built-in scene) with overrides.
sim::SceneFile read_scene_named(const std::string& name, const std::vector<sim::Override>& overrides);
// The YAML text of the same (a file's contents or a built-in scene's).
std::string scene_text_named(const std::string& name);

}  // namespace unfurl::app
