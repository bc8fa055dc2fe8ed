// A finished study opened in the workbench (`unfurl gui --study STUDY
// --out DIR`): the rows of its cases as `unfurl study` recorded them in
// DIR, a table order, and which case is on show. Picking a case re-runs it
// on the simulation thread (study_cases.hpp: the case's scene), so it can
// be played, plotted and edited like any scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/studies/case_result.hpp"

namespace unfurl::app {

struct StudyBrowser {
  std::string study_path;
  std::string dir;
  studies::Study study;
  studies::CaseColumns columns;
  std::vector<studies::StudyCase> cases;
  std::vector<studies::CaseResult> rows;  // the finished cases, in case order
  std::vector<int> order;        // indices into rows, as the table shows them
  std::string shown;             // the id of the case on show; "" for none
  // The table's columns (as numbered below), at most 64 (Dear ImGui's
  // limit): id, status, the headline outputs, then the inputs.
  std::vector<int> table_columns;

  const studies::StudyCase* find_case(const std::string& id) const;
  // Sorts the table by column `column` (0 id, 1 status, then the inputs,
  // then the outputs); NaN last either way.
  void sort(int column, bool ascending);
  // Column k's value in row r, for sorting and display (NaN for id/status).
  double value(const studies::CaseResult& r, int column) const;
  int column_count() const { return 2 + static_cast<int>(columns.inputs.size() + columns.outputs.size()); }
  std::string column_name(int column) const;
};

// The elements a case's failure put into its scene (a broken or weakened
// spring, a stuck hinge's stop, an added friction), as the parameter paths
// that name them ("springs.j1", "latches.8", "friction.j4"): they are the
// study file's, not the scene's, so the workbench shows them read-only and
// refuses an edit of them. `scene` is the case's scene, failure applied.
std::vector<std::string> failure_elements(const sim::Scene& scene, const studies::StudyFailure& failure);

// Whether an edit's path reaches into one of `elements`.
bool edits_element(const std::string& path, const std::vector<std::string>& elements);

// Reads the study file and the case records DIR holds. Throws
// std::runtime_error when the study does not read or DIR holds no finished
// case of it.
StudyBrowser open_study(const std::string& study_path, const std::string& dir);

}  // namespace unfurl::app
