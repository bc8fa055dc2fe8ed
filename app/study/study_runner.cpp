#include "study_runner.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "unfurl/io/output_file.hpp"
#include "unfurl/io/run_files.hpp"
#include "unfurl/io/study_files.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/clearance.hpp"
#include "commands/scene_clearance.hpp"

namespace unfurl::app {

StudyRun::StudyRun(const studies::Study& study, SweepOptions options, const std::atomic<bool>& cancel)
    : study_(study), options_(std::move(options)), cancel_(cancel) {
  const sim::SceneFile nominal = studies::nominal_scene(study);
  nominal_ = nominal.scene;
  // Read once: every case has the nominal scene's bodies and meshes.
  solids_ = scene_solids(nominal_, nominal.visuals, nullptr);
  columns_ = studies::case_columns(study_, nominal_);
  cases_ = studies::study_cases(study_);
  results_.resize(cases_.size());
  for (std::size_t i = 0; i < cases_.size(); ++i) {
    results_[i] = io::read_case_record(columns_, options_.dir, cases_[i].id);
    if (!results_[i]) pending_.push_back(i);
  }
}

std::optional<std::string> StudyRun::run_case(std::size_t i) const {
  const studies::StudyCase& c = cases_[i];
  studies::CaseResult result;
  try {
    // Cases that run side by side already take every core.
    const sim::RunThreads threads =
        options_.jobs > 1 || options_.over_mpi ? sim::RunThreads::one : sim::default_run_threads();
    const studies::CaseRun run = studies::simulate_case(study_, c, &cancel_, threads);
    if (run.run.status == sim::RunStatus::cancelled) return std::nullopt;
    const sim::Clearance clearance = studies::check_clearance(run.scene, solids_, run.run.trajectory);
    result = studies::case_result(study_, nominal_, c, run, &clearance);
    if (options_.keep_runs) {
      const std::string dir = options_.dir + "/cases/" + c.id;
      io::make_directory(dir);
      sim::RunSummary summary = sim::summarize(run.scene, run.run);
      summary.clearance = clearance;
      io::write_trajectory_csv(run.scene, run.run.trajectory, dir + "/trajectory.csv");
      io::write_loads_csv(run.scene, run.run.trajectory, dir + "/loads.csv");
      io::write_events_csv(run.scene, run.run.trajectory, dir + "/events.csv");
      io::write_summary_json(run.scene, run.run, summary, dir + "/summary.json");
    }
  } catch (const io::OutputError&) {
    throw;
  } catch (const std::exception& e) {
    result = studies::CaseResult{};
    result.id = c.id;
    result.failure = c.failure ? c.failure->describe() : "";
    result.inputs = c.inputs;
    result.status = studies::CaseStatus::failed;
    result.reason = std::string("the case's scene: ") + e.what();
    result.outputs.assign(columns_.outputs.size(), std::nan(""));
  }
  return io::case_record(columns_, result);
}

void StudyRun::record(std::size_t i, const std::string& text) {
  std::optional<studies::CaseResult> r = io::parse_case_record(columns_, text);
  if (!r) throw std::runtime_error("case " + cases_[i].id + ": a record that does not parse");
  io::write_case_record(options_.dir, cases_[i].id, text);
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_now_;
  if (r->status == studies::CaseStatus::failed) ++failed_now_;
  results_[i] = std::move(r);
  show_progress();
}

// A line redrawn in place on a terminal; elsewhere (a batch job's log) a
// line at every tenth of the study.
void StudyRun::show_progress() {
  if (options_.quiet) return;
  const auto now = std::chrono::steady_clock::now();
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  const long total = static_cast<long>(pending_.size());
  if (terminal && drawn_ && now - shown_ < std::chrono::milliseconds(200) && done_now_ < total) return;
  if (!terminal && done_now_ * 10 < next_tenth_ * total && done_now_ < total) return;
  while (next_tenth_ * total <= done_now_ * 10) ++next_tenth_;
  shown_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = elapsed / static_cast<double>(done_now_) * static_cast<double>(total - done_now_);
  std::fprintf(stderr, "%sstudy: %ld of %ld cases, %ld failed, %.0f s elapsed, about %.0f s left%s",
               terminal ? "\r" : "", done_now_, total, failed_now_, elapsed, left, terminal ? "   " : "\n");
  std::fflush(stderr);
}

void StudyRun::finish_progress() {
  if (drawn_ && ::isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
}

void run_on_threads(StudyRun& run, std::atomic<std::size_t>& next, int threads) {
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    try {
      for (std::size_t k; !run.cancel() && (k = next++) < run.pending().size();)
        if (const auto record = run.run_case(run.pending()[k])) run.record(run.pending()[k], *record);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

void run_locally(StudyRun& run) {
  std::atomic<std::size_t> next{0};
  run_on_threads(run, next, run.options().jobs);
}

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::atoi(v) > 1;
  return false;
}

}  // namespace unfurl::app
