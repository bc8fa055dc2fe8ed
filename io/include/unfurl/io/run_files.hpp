// The files `unfurl simulate` writes: trajectory.csv, loads.csv, events.csv
// and summary.json (each complete or absent).
#pragma once

#include <string>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::io {

void write_trajectory_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path);
// loads.csv: t, then per joint tau_spring.J, tau_damper.J, tau_latch.J
// (only where the joint has the element), reaction.J.fx .. .mz (the wrench
// from the parent on the child about the hinge point, child frame), then
// loop_force.L.C per active loop component (on the split body, its frame).
void write_loads_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path);
void write_events_csv(const Scene& scene, const Trajectory& trajectory, const std::string& path);
void write_summary_json(const Scene& scene, const RunResult& result, const RunSummary& summary,
                        const std::string& path);

}  // namespace unfurl::io
