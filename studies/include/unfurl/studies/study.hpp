// A deployment study (`unfurl study`): one scene, the values that vary (by
// their --set paths) and the failures to inject, each case one independent
// run. The file format is documented in assets/studies/README.md.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::studies {

// One varied scene value. Lists and grids give its values; distributions
// draw it per case. A `scale` variable multiplies the scene's value.
struct StudyVariable {
  enum class Kind { values, grid, uniform, normal, lognormal };
  std::string path;    // a --set path; springs.J.preload is the preload factor
  Kind kind = Kind::values;
  std::vector<double> values;  // values, or the grid's points
  double a = 0, b = 0;         // uniform: min, max; normal: mean, sigma; lognormal: mu, sigma of ln
  double lo = -std::numeric_limits<double>::infinity();  // truncation (normal, lognormal)
  double hi = std::numeric_limits<double>::infinity();
  bool scale = false;
  double nominal = 0;  // the scene's value (1 for a preload factor)

  bool random() const { return kind == Kind::uniform || kind == Kind::normal || kind == Kind::lognormal; }
  // The column name in cases.csv.
  std::string label() const;
  // Whether the path is the virtual preload factor of a spring.
  bool is_preload() const;
};

// A fault injected into the nominal scene, one case each.
struct StudyFailure {
  enum class Kind { latch_fails, spring_breaks, preload_loss, stuck, extra_friction };
  Kind kind = Kind::latch_fails;
  std::string joint;
  double fraction = 0;  // preload_loss: the part of the preload lost
  double coulomb = 0;   // extra_friction: added Coulomb torque, N m (friction.hpp)
  double viscous = 0;   // extra_friction: added viscous coefficient, N m s/rad

  // "latch-j3-fails", used in the case id.
  std::string id() const;
  // "latch j3 never engages", for the tables.
  std::string describe() const;
  // The joints whose latch the failure takes out of the scene: a run of the
  // case counts them as never latched.
  std::vector<std::string> removed_latches() const;
};

struct Study {
  std::string source;        // the study file
  std::string scene;         // as the file names it
  std::string scene_text;    // the scene's YAML
  std::string scene_source;  // where it came from (a path, or "built-in NAME")
  std::vector<sim::Override> settings;   // the study's fixed --set values (run settings, ...)
  std::vector<StudyVariable> variables;  // `*` paths expanded
  bool zip = false;          // lists and grids: element by element, not every combination
  unsigned long seed = 1;
  long runs = 0;             // random cases
  std::vector<StudyFailure> failures;
  std::string overlay_joint; // the joint whose angle every case draws on one plot
};

// Reads a study file; errors (input::InputError) name the file, line, column and
// field, as for scenes.
Study read_study_file(const std::string& path);
Study read_study_text(const std::string& text, const std::string& source, const std::string& directory);

// The nominal scene with the study's settings.
sim::SceneFile nominal_scene(const Study& study);

}  // namespace unfurl::studies
