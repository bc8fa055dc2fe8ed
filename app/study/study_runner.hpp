// Runs the cases of a study that its directory does not hold yet: on local
// threads (--jobs), or over MPI ranks when started by mpirun, rank 0 handing
// out one case at a time to whichever rank asks (runs differ in length) and
// writing every record. Each record is written as its case finishes, so an
// interrupted study resumes where it stopped.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/studies/body_solids.hpp"
#include "unfurl/studies/case_result.hpp"

namespace unfurl::app {

struct SweepOptions {
  std::string dir;
  int jobs = 1;  // threads per process
  bool keep_runs = false;
  bool quiet = false;
  bool over_mpi = false;  // one of several processes, each with its cases
};

class StudyRun {
 public:
  StudyRun(const studies::Study& study, SweepOptions options, const std::atomic<bool>& cancel);

  const studies::Study& study() const { return study_; }
  const sim::Scene& nominal() const { return nominal_; }
  const studies::CaseColumns& columns() const { return columns_; }
  const std::vector<studies::StudyCase>& cases() const { return cases_; }
  const SweepOptions& options() const { return options_; }
  const std::atomic<bool>& cancel() const { return cancel_; }

  // The cases still to run (those without a record in the directory).
  const std::vector<std::size_t>& pending() const { return pending_; }
  // Runs case i here; its record, or nullopt when cancelled. A case that
  // cannot even be set up (its values make an invalid scene) is recorded
  // as failed.
  std::optional<std::string> run_case(std::size_t i) const;
  // Stores and writes a case's record (thread-safe) and shows progress.
  void record(std::size_t i, const std::string& record);

  // Every case's result, in case order (nullopt: not finished).
  const std::vector<std::optional<studies::CaseResult>>& results() const { return results_; }
  void finish_progress();

 private:
  void show_progress();

  const studies::Study& study_;
  SweepOptions options_;
  const std::atomic<bool>& cancel_;
  sim::Scene nominal_;
  studies::BodySolids solids_;
  studies::CaseColumns columns_;
  std::vector<studies::StudyCase> cases_;
  std::vector<std::size_t> pending_;
  std::vector<std::optional<studies::CaseResult>> results_;
  mutable std::mutex mutex_;
  long done_now_ = 0, failed_now_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), shown_{};
  bool drawn_ = false;
  int next_tenth_ = 1;
};

// Runs every pending case on `jobs` threads of this process.
void run_locally(StudyRun& run);
// Runs pending cases on `threads` threads (this one included), each taking
// the next index from `next` until none is left or the run is cancelled.
void run_on_threads(StudyRun& run, std::atomic<std::size_t>& next, int threads);

// Whether this process was started by mpirun with more than one rank.
bool launched_by_mpirun();
// Runs the pending cases over the MPI ranks. Returns true on rank 0 (which
// then holds every record); false on the others, which have nothing to write.
bool run_over_mpi(StudyRun& run, int& processes);

}  // namespace unfurl::app
