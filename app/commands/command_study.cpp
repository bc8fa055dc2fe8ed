// unfurl study: run a study (off-nominal values, Monte Carlo draws, injected
// failures) and write its tables, statistics and plots.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "unfurl/io/output_file.hpp"
#include "study_plots.hpp"
#include "study_runner.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl study STUDY.yaml --out DIR [--jobs N] [--keep-runs] [--quiet]\n"
    "       mpirun -n K unfurl study STUDY.yaml --out DIR\n"
    "\n"
    "Runs every case of a study (assets/studies/README.md describes the file) and\n"
    "writes into DIR:\n"
    "  cases.csv        one row per case: its values, status, latch times and torques,\n"
    "                   peak hinge loads, largest loop gap, final energy, wall time\n"
    "  summary.json     counts by status, statistics of every output over the deployed\n"
    "                   cases, and the input that drives each output most\n"
    "  STUDY.md         the same as a report, with the plots (*.png)\n"
    "  cases/ID/        each case's record (and with --keep-runs its run files, which\n"
    "                   `unfurl render --trajectory DIR/cases/ID/trajectory.csv` draws)\n"
    "\n"
    "Rerunning the same command on the same DIR skips the cases already finished.\n"
    "\n"
    "options:\n"
    "  --out DIR      output directory (required)\n"
    "  --jobs N       cases run at once in this process (default: the number of cores;\n"
    "                 1 per rank under mpirun)\n"
    "  --keep-runs    also write each case's trajectory, loads, events and summary\n"
    "  --quiet        no progress\n"
    "\n"
    "Exit status: 0 done (whatever the cases' outcomes), 2 a bad study or scene,\n"
    "64 bad usage, 73 DIR cannot be written, 128+N stopped by signal N (the finished\n"
    "cases are kept; rerun to go on).\n";

// A directory holds one study's cases: another study's would be mixed in.
void claim_directory(const std::string& dir, const std::string& study_text) {
  io::make_directory(dir);
  const std::string copy = dir + "/study.yaml";
  std::error_code ec;
  if (std::filesystem::exists(copy, ec)) {
    if (io::read_text_file(copy) != study_text)
      throw UsageError(dir +
                       " holds the cases of another study (its study.yaml differs); use another --out or remove it");
    return;
  }
  io::OutputFile out(copy);
  out.stream() << study_text;
  out.commit();
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s = "unfurl study";
  for (const std::string& a : argv) s += " " + a;
  return s;
}

}  // namespace

int command_study(const std::vector<std::string>& argv) {
  const Args args(argv, {"--out", "--jobs"}, {"--help", "-h", "--keep-runs", "--quiet"});
  if (args.has("--help") || args.has("-h")) {
    std::printf("%s", kHelp);
    return 0;
  }
  if (args.positionals().size() != 1) throw UsageError("study takes one STUDY file (see --help)");
  if (!args.get("--out")) throw UsageError("study needs --out DIR");
  const bool mpi = launched_by_mpirun();
  const double jobs = args.number("--jobs", mpi ? 1.0 : std::max(1u, std::thread::hardware_concurrency()));
  if (jobs < 1 || jobs > 1024 || jobs != static_cast<int>(jobs))
    throw UsageError("--jobs: expected a whole number in 1..1024");

  const std::string path = args.positionals()[0];
  const studies::Study study = studies::read_study_file(path);
  SweepOptions options{*args.get("--out"), static_cast<int>(jobs), args.has("--keep-runs"), args.has("--quiet"), mpi};
  claim_directory(options.dir, io::read_text_file(path));

  const auto start = std::chrono::steady_clock::now();
  const InterruptScope interrupt;
  StudyRun run(study, options, interrupt.flag());
  int processes = 1;
  if (mpi) {
    if (!run_over_mpi(run, processes)) return 0;
  } else {
    run_locally(run);
  }
  run.finish_progress();

  std::vector<studies::CaseResult> results;
  for (const auto& r : run.results())
    if (r) results.push_back(*r);
  io::StudyReport report{study,
                         run.columns(),
                         results,
                         static_cast<long>(run.cases().size()),
                         static_cast<long>(run.cases().size() - run.pending().size()),
                         studies::study_statistics(run.columns(), results, studies::inputs_moved_together(study)),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                         processes,
                         options.jobs,
                         command_line(argv)};
  io::write_cases_csv(report, options.dir + "/cases.csv");
  io::write_study_summary_json(report, options.dir + "/summary.json");
  const std::vector<std::string> plots = write_study_plots(report, options.dir);
  io::write_study_markdown(report, plots, options.dir + "/STUDY.md");

  const studies::StudyStatistics& st = report.statistics;
  if (!options.quiet)
    std::printf(
        "study        %s: %ld of %ld cases in %.1f s (%d process%s, %d job%s)\n"
        "status       %ld deployed, %ld not deployed, %ld failed\n"
        "files        %s/{cases.csv,summary.json,STUDY.md}\n",
        path.c_str(), st.cases, report.total_cases, report.wall_time_s, processes, processes == 1 ? "" : "es",
        options.jobs, options.jobs == 1 ? "" : "s", st.deployed, st.not_deployed, st.failed, options.dir.c_str());
  if (interrupt.signal()) {
    std::fprintf(stderr, "unfurl study: interrupted by %s: %ld of %ld cases are finished and kept; rerun to go on\n",
                 interrupt.signal_name(), st.cases, report.total_cases);
    return interrupt.exit_status();
  }
  return 0;
}

}  // namespace unfurl::app
