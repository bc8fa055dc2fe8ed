// What `unfurl study` writes into its directory: per case a record
// (cases/ID/case.csv, cases/ID/angle.csv) written as the case finishes, so
// an interrupted study resumes; and once all are done cases.csv,
// summary.json and STUDY.md. Every file is complete or absent.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unfurl/studies/case_result.hpp"
#include "unfurl/studies/study_statistics.hpp"

namespace unfurl::io {

// The whole of a text file ("" when it cannot be read).
std::string read_text_file(const std::string& path);

// The values of cases.csv's column `name` (its header without the unit)
// over the rows of a status ("deployed"), empty cells left out. Throws
// std::runtime_error when the file or the column is missing.
std::vector<double> read_cases_column(const std::string& path, const std::string& name,
                                      const std::string& status = "deployed");

// The header line of cases.csv (and of each case record).
std::string cases_header(const studies::CaseColumns& columns);
// One row of cases.csv; numbers round-trip exactly, NaN is empty.
std::string case_row(const studies::CaseResult& r);

// A case's record as text (its case.csv, then a form feed, then its
// angle.csv), for a file or a message between processes.
std::string case_record(const studies::CaseColumns& columns, const studies::CaseResult& r);
// Parses a record; nullopt when it was written for other columns.
std::optional<studies::CaseResult> parse_case_record(const studies::CaseColumns& columns, const std::string& record);

// Writes the record under dir/cases/ID/.
void write_case_record(const std::string& dir, const std::string& id, const std::string& record);
// The record of a finished case, if dir holds one for these columns.
std::optional<studies::CaseResult> read_case_record(const studies::CaseColumns& columns, const std::string& dir,
                                                    const std::string& id);

struct StudyReport {
  const studies::Study& study;
  const studies::CaseColumns& columns;
  const std::vector<studies::CaseResult>& results;  // in case order
  long total_cases = 0;
  long resumed = 0;  // cases read back from an earlier, interrupted run
  studies::StudyStatistics statistics;
  double wall_time_s = 0;
  int processes = 1, jobs = 1;
  std::string command;
};

void write_cases_csv(const StudyReport& report, const std::string& path);
void write_study_summary_json(const StudyReport& report, const std::string& path);
void write_study_markdown(const StudyReport& report, const std::vector<std::string>& pictures, const std::string& path);

}  // namespace unfurl::io
