// Scene files (YAML): loading, --set overrides and validation. Every error
// names the file, line, column and field (input::InputError); the format is
// documented in assets/scenes/README.md. A file gives the Scene (what the
// solver runs) and its visuals (what the renderer draws).
#pragma once

#include <string>
#include <vector>

#include "unfurl/input/input_error.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/visuals.hpp"

namespace unfurl::sim {

// A "--set path=value" override: path is the key path in the file, with
// list elements chosen by index or by their name (or joint, or body).
struct Override {
  std::string path;
  std::string value;  // YAML
};
// Parses "path=value"; throws input::InputError when there is no '='.
Override parse_override(const std::string& assignment);

// A scene's text with overrides applied, as YAML that reads back to the
// same scene, headed by comments naming the changes. Throws input::InputError as
// reading would.
std::string scene_text_with(const std::string& text, const std::string& source, const std::vector<Override>& overrides);

// The paths a pattern stands for: each `*` in `path` ranges over the
// elements of a list, named as a --set path names them ("springs.*.stiffness"
// -> "springs.j1.stiffness", ...). Throws input::InputError when none exists.
std::vector<std::string> expand_scene_path(const std::string& text, const std::string& source,
                                           const std::string& path);
// The number at a --set path of a scene's text; throws input::InputError when
// there is none.
double scene_number(const std::string& text, const std::string& source, const std::string& path);

struct SceneFile {
  Scene scene;
  SceneVisuals visuals;
};

SceneFile read_scene_file(const std::string& path, const std::vector<Override>& overrides = {});
SceneFile read_scene_text(const std::string& text, const std::string& source,
                          const std::vector<Override>& overrides = {});

// A scene as a scene file that reads back to the same scene (and run),
// headed by `comment` (its lines become # lines).
std::string write_scene_text(const SceneFile& file, const std::string& comment = "");

// A scene with --set overrides applied (through its file text: the paths
// are the file's). Throws input::InputError as reading would.
SceneFile apply_overrides(const SceneFile& file, const std::vector<Override>& overrides);

// The Scene alone.
Scene load_scene_file(const std::string& path, const std::vector<Override>& overrides = {});
Scene load_scene_text(const std::string& text, const std::string& source,
                      const std::vector<Override>& overrides = {});

// The scenes built into the binary (so `unfurl simulate` needs no files).
std::vector<std::string> builtin_scene_names();
// Throws input::InputError for an unknown name.
SceneFile read_builtin_scene(const std::string& name, const std::vector<Override>& overrides = {});
Scene load_builtin_scene(const std::string& name, const std::vector<Override>& overrides = {});
const std::string& builtin_scene_text(const std::string& name);

}  // namespace unfurl::sim
