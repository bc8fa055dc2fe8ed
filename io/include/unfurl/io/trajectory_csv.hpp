// Reads back a trajectory.csv written by `unfurl simulate` (and the
// events.csv and loads.csv beside it) for the scene it came from, so `render` can draw a
// run without simulating it again.
#pragma once

#include <string>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::io {

// Throws std::runtime_error naming the file, line and column on a mismatch
// (a joint of the scene missing from the file, a malformed number).
Trajectory read_trajectory_csv(const Scene& scene, const std::string& path);

}  // namespace unfurl::io
