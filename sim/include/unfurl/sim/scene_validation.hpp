// The rules every scene keeps, however it was made (a file, a program, a
// binding): validate() finishes a scene (the model's derived tables, the
// neutral positions of ball and free joints) and checks it, with errors by
// field path as a scene file would spell it ("bodies[3] (panel_A1).inertia",
// "springs[0].stiffness"). The file reader adds where in the file the field
// is; a scene built in code gets the path alone.
#pragma once

#include <string>
#include <vector>

#include "unfurl/input/input_error.hpp"
#include "unfurl/sim/scene.hpp"

namespace unfurl::sim {

class SceneInvalid : public input::InputError {
 public:
  SceneInvalid(std::string field, std::string reason)
      : InputError(field.empty() ? reason : field + ": " + reason),
        field_(std::move(field)),
        reason_(std::move(reason)) {}
  // The path of the field, and what is wrong with its value.
  const std::string& field() const { return field_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string field_, reason_;
};

// Throws SceneInvalid at the first rule the scene breaks. Needs the model's
// bodies, joints and parents, the elements, loops, settings and whatever
// initial values are given (q0 may be empty: every coordinate then starts
// at its joint's neutral position).
void validate(Scene& scene);
// The part of validate() that needs nothing but the tree: bodies, joints,
// parents, the model's coordinate tables, and q0 and dq0 at the joints'
// neutral positions and at rest where they are empty (what initial values
// given by joint need).
void validate_model(Scene& scene);

// What is valid but likely a mistake, each "field: what", for the front
// ends to show: an initial angle of more than a turn (degrees given where
// radians are meant: `j1: -90`).
std::vector<std::string> scene_warnings(const Scene& scene);

// Body, joint, loop and element names: letters, digits, '_' and '-' (at
// most 64), so they stand as they are in CSV headers, --set paths and file
// names.
bool is_valid_name(const std::string& name);

// "bodies[3] (panel_A1)": how a field path names body i (the free base is
// "base").
std::string body_field(const Scene& scene, int i);
// "springs[2]": each element by its list and its index there.
std::vector<std::string> element_fields(const Scene& scene);

// Range checks that throw SceneInvalid at `field`.
void check_positive(double x, const std::string& field);
void check_non_negative(double x, const std::string& field);

// Limits of what a scene may ask for (each error message names them).
inline constexpr double kLargestClosureTolerance = 0.05;  // m or rad
inline constexpr long kMostSteps = 1'000'000'000'000;

}  // namespace unfurl::sim
