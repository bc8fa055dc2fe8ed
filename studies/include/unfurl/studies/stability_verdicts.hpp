// What a stability run's figures mean: whether it ended as its case
// expects, which branch each loop took, how fast an open start closed.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/trajectory.hpp"
#include "unfurl/studies/stability_results.hpp"

namespace unfurl::studies {

// Finished, or failed the expected check (a probe: either).
bool as_expected(const StabilityResult& r);

// Which way each loop went: the joints on the loop's path that opened
// (moved by more than 0.1 rad) and those that held (within 0.01 rad).
std::vector<std::string> describe_branches(const sim::Scene& scene, const sim::Trajectory& trajectory);

// The largest geometric gap of any loop in a sample, metres or radians.
double largest_gap(const sim::Sample& s);

// The first time the largest loop gap is below `level` (NaN: never).
double closing_time(const sim::Trajectory& tr, double level);

}  // namespace unfurl::studies
