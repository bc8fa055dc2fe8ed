// Runs kept for comparison (pinned) and the table of their differences from
// the current run: the figures an engineer reads off a deployment (when it
// latched, how hard, where the energy went, how well the loops closed).
#pragma once

#include <imgui.h>

#include <memory>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::app {

// One figure of a run; NaN when the run does not have it (a latch that
// never engaged, a deployment that did not complete).
struct RunFigure {
  std::string name;  // "deployment time, s", "latch j1, s", ...
  double value = 0;
};

std::vector<RunFigure> run_figures(const sim::RunSummary& summary);

// What a pinned run can be drawn against: runs of the same scene with the
// same bodies, coordinates and loops (a study's failure case may add or
// remove a latch and still compares).
struct SceneShape {
  std::string scene;
  int bodies = 0, coordinates = 0, loops = 0;
  bool operator==(const SceneShape& o) const {
    return scene == o.scene && bodies == o.bodies && coordinates == o.coordinates && loops == o.loops;
  }
};

SceneShape scene_shape(const sim::Scene& scene);

struct PinnedRun {
  std::string name;
  char name_field[64] = "";  // the Runs tab's editable copy of the name
  SceneShape shape;
  sim::Trajectory trajectory;
  std::shared_ptr<const sim::RunSummary> summary;
  ImU32 color = 0;
  bool shown = true;
};

// The k-th pinned run's colour: translucent hues apart from the joints'
// palette, visible on the dark background.
ImU32 pinned_color(int k);

// A row of the difference table: the current run's figure and each pinned
// run's (NaN where a run lacks it). Rows follow the current run's figures,
// then any a pinned run has beyond them.
struct ComparisonRow {
  std::string name;
  double current = 0;
  std::vector<double> pinned;
};

std::vector<ComparisonRow> compare_runs(const sim::RunSummary& current, const std::vector<PinnedRun>& pinned);

}  // namespace unfurl::app
