// The columns of trajectory.csv, loads.csv and sensors.csv, described once: each column's
// name, unit and frame (its header cell reads "name [unit; frame]": no comma,
// so any CSV reader splits the header as the rows), how a
// sample gives its value and, for what is read back, how it takes it. The
// writer and the reader (run_files.hpp) both go by this description, and
// docs/OUTPUTS.md tables it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::io {

struct RunColumn {
  std::string name;   // "q.j1"
  std::string unit;   // "rad"; "" for a pure number
  std::string frame;  // "child body frame"; "" where none applies
  std::function<double(const sim::Sample&)> value;
  // Sets the value on a sample being read back; empty for a column derived
  // from the others (not read back).
  std::function<void(sim::Sample&, double)> set;
};

// "q.j1 [rad]", "hinge_force.j1.x [N; child body frame]", "t [s]".
std::string header_cell(const RunColumn& column);
// The name in a header cell (what precedes " [").
std::string column_name(const std::string& header_cell);

// The columns for a scene's run (the trajectory gives the layout, the loop
// components and the load columns).
std::vector<RunColumn> trajectory_columns(const sim::Scene& scene, const sim::Trajectory& trajectory);
std::vector<RunColumn> load_file_columns(const sim::Scene& scene, const sim::Trajectory& trajectory);
// sensors.csv: t, then every sensor's readings.
std::vector<RunColumn> sensor_file_columns(const sim::Trajectory& trajectory);

// A sample sized for the trajectory's columns (state, rates, gaps, loads),
// to be filled by set().
sim::Sample empty_sample(const sim::Scene& scene, const sim::Trajectory& trajectory);

}  // namespace unfurl::io
