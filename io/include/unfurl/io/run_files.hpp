// The files `unfurl simulate` writes: trajectory.csv, loads.csv, events.csv,
// sensors.csv (with sensors) and summary.json (each complete or absent), and the reader of a run's
// files, so `render` can draw a run without simulating it again. The CSV
// columns are run_columns.hpp's, a header cell "name [unit; frame]".
#pragma once

#include <string>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::io {

void write_trajectory_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path);
void write_loads_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path);
// sensors.csv: the scene's sensors' readings at every sample (a scene with
// sensors).
void write_sensors_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path);
void write_events_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path);
void write_summary_json(const sim::Scene& scene, const sim::RunResult& result, const sim::RunSummary& summary,
                        const std::string& path);
// summary.json's text.
std::string summary_json(const sim::Scene& scene, const sim::RunResult& result, const sim::RunSummary& summary);

// A trajectory.csv for the scene it came from, with the events.csv,
// loads.csv and sensors.csv beside it where they are. Throws std::runtime_error naming the
// file, line and column on a mismatch (a joint of the scene missing from
// the file, a malformed number).
sim::Trajectory read_trajectory_csv(const sim::Scene& scene, const std::string& path);

}  // namespace unfurl::io
