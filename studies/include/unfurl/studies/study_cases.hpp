// The cases of a study: the nominal case first, then every combination (or
// zip) of the lists and grids, or `runs` random draws, then one case per
// failure. A case's id and values depend only on the study file, never on
// the order in which cases run: random case k draws from its own generator
// seeded by (seed, k), so a study can be resumed or spread over processes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/studies/study.hpp"

namespace unfurl::studies {

struct StudyCase {
  std::string id;              // "nominal", "case-0042", "fail-latch-j3"
  std::vector<double> inputs;  // per variable, the value it takes
  std::optional<StudyFailure> failure;
};

std::vector<StudyCase> study_cases(const Study& study);

// The scene of one case: the study's scene with its settings, the case's
// values and its failure applied.
sim::Scene case_scene(const Study& study, const StudyCase& c);
// The same with the scene's visuals, and `edits` (--set overrides) applied
// over the case's values: the workbench's edits of a case it shows.
sim::SceneFile case_scene_file(const Study& study, const StudyCase& c, const std::vector<sim::Override>& edits = {});

}  // namespace unfurl::studies
