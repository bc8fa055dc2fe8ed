// The files `unfurl simulate` writes: trajectory.csv, events.csv and
// summary.json (each complete or absent).
#pragma once

#include <string>

#include "scene.hpp"
#include "simulation.hpp"
#include "summary.hpp"

namespace unfurl::app {

void write_trajectory_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path);
void write_events_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path);
void write_summary_json(const Scene& scene, const RunResult& result, const RunSummary& summary,
                        const std::string& path);

}  // namespace unfurl::app
