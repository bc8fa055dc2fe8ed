// What a study records of one case: a row of cases.csv. Its columns are
// fixed by the study and its scene (case_columns), so rows can be written
// by any process, read back on a resume and compared across runs.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "unfurl/sim/clearance_result.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/study_cases.hpp"

namespace unfurl::studies {

enum class CaseStatus { deployed, not_deployed, failed };
const char* case_status_name(CaseStatus status);  // "deployed", "not deployed", "failed"

// The numeric columns of cases.csv after id, failure, status and reason:
// the varied inputs, then the outputs.
struct CaseColumns {
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
  // The outputs a study summarizes and ranks drivers for.
  static const std::vector<std::string>& headline();
};
// The unit of an output ("peak_hinge_force.j3": "N"; "steps": "").
std::string output_unit(const std::string& output);
CaseColumns case_columns(const Study& study, const sim::Scene& nominal);

struct CaseResult {
  std::string id;
  std::string failure;  // the injected failure, "" for none
  CaseStatus status = CaseStatus::failed;
  std::string reason;   // why not deployed or failed
  std::vector<double> inputs;
  std::vector<double> outputs;  // as CaseColumns::outputs; NaN where there is none
  // The overlay joint's angle at fixed times (for the study's overlay plot).
  std::vector<double> angle_t, angle;
};

struct CaseRun {
  sim::Scene scene;
  sim::RunResult run;
};

// Runs one case; `cancel` stops it early (the result is then not recorded).
CaseRun simulate_case(const Study& study, const StudyCase& c, const std::atomic<bool>* cancel = nullptr,
                      sim::RunThreads threads = sim::default_run_threads());
// The case's row, from its run. `nominal` gives the latches and joints the
// columns name (a failed latch is missing from the case's own scene);
// `clearance`, the run's clearance where it was checked.
CaseResult case_result(const Study& study, const sim::Scene& nominal, const StudyCase& c, const CaseRun& run,
                       const sim::Clearance* clearance = nullptr);

// The value of output `name` in a row, NaN when absent.
double output_value(const CaseColumns& columns, const CaseResult& r, const std::string& name);

}  // namespace unfurl::studies
