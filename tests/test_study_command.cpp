// `unfurl study` end to end: the tables, a resumed study, an interrupted
// one, and the same study over two MPI ranks, each giving the same
// cases.csv (but for the wall times) as one uninterrupted local run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = std::string(UNFURL_SOURCE_DIR) + "/tests/studies/small_monte_carlo.yaml";
const std::string kOther = std::string(UNFURL_SOURCE_DIR) + "/assets/studies/pantograph_failures.yaml";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("unfurl_study_" + name);
  fs::remove_all(dir);
  return dir;
}

test::CommandOutcome run_study(const std::string& study, const fs::path& out, const std::string& more = "") {
  return test::run_command(std::string(UNFURL_BINARY) + " study " + study + " --out " + out.string() + " --quiet " + more);
}

// cases.csv without its last column (the wall time, which differs run to run).
std::vector<std::string> table_without_wall_time(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(line.substr(0, line.rfind(',')));
  return rows;
}

TEST(StudyCommand, WritesTheTablesTheReportAndThePlots) {
  const fs::path out = fresh_dir("tables");
  const test::CommandOutcome o = run_study(kSmall, out, "--jobs 2");
  ASSERT_EQ(o.code, 0) << o.output;
  const auto rows = table_without_wall_time(out / "cases.csv");
  ASSERT_EQ(rows.size(), 7u);  // header + nominal + 4 draws + 1 failure
  EXPECT_EQ(rows[1].rfind("nominal,,deployed,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[6].rfind("fail-latch-j3-fails,latch j3 never engages,not deployed,never latched: j3,", 0), 0u) << rows[6];
  // Every row parses to the header's columns with Python's csv module.
  const test::CommandOutcome py = test::run_command(
      "python3 -c \"import csv,sys; r=list(csv.reader(open(sys.argv[1]))); "
      "assert all(len(x)==len(r[0]) for x in r), 'ragged'; print(len(r))\" " + (out / "cases.csv").string());
  EXPECT_EQ(py.output, "7\n");
  const std::string summary = test::text_of(out / "summary.json");
  EXPECT_NE(summary.find("\"deployed\": 5"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"not_deployed\": 1"), std::string::npos) << summary;
  const std::string report = test::text_of(out / "STUDY.md");
  EXPECT_NE(report.find("is driven most by `springs."), std::string::npos) << report;
  // The pantograph's latched loops are redundant: every case says so, with
  // the minimum-norm peak beside the determinate ones.
  EXPECT_NE(report.find("**Warning:** in 6 of 6 cases the hinge loads are indeterminate"), std::string::npos)
      << report;
  EXPECT_NE(report.find("| nominal | deployed | "), std::string::npos) << report;
  EXPECT_NE(rows[0].find("loads_determinate,indeterminate_time [s],indeterminate_from [s],"
                         "peak_hinge_force_indeterminate [N]"),
            std::string::npos)
      << rows[0];
  // The clearance: a column per case, and (where the meshes can be read)
  // a section of the report: the pantograph's panels abut when deployed
  // but do not overlap.
  EXPECT_NE(rows[0].find(",min_clearance [m],contacts,"), std::string::npos) << rows[0];
#ifdef UNFURL_WITH_RENDER
  EXPECT_NE(report.find("## Clearance\n\nNo two bodies that are not jointed together touch in any case"),
            std::string::npos)
      << report;
  for (const char* png : {"hist_deployment_time.png", "hist_peak_latch_torque.png", "overlay_angles.png",
                          "scatter_deployment_time.png", "failures_deployment_time.png", "failures_peak_latch_torque.png",
                          "failures_peak_hinge_force.png", "failures_torque_margin.png", "failures_min_clearance.png"})
    EXPECT_TRUE(fs::is_regular_file(out / png)) << png;
#endif
}

TEST(StudyCommand, ResumesWhereItStoppedAndRefusesAnotherStudysDirectory) {
  const fs::path whole = fresh_dir("whole"), resumed = fresh_dir("resumed");
  ASSERT_EQ(run_study(kSmall, whole, "--jobs 1").code, 0);
  fs::copy(whole, resumed, fs::copy_options::recursive);
  fs::remove_all(resumed / "cases" / "case-0002");
  fs::remove_all(resumed / "cases" / "fail-latch-j3-fails");
  fs::remove(resumed / "cases.csv");
  const test::CommandOutcome again = run_study(kSmall, resumed, "--jobs 1");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_EQ(table_without_wall_time(resumed / "cases.csv"), table_without_wall_time(whole / "cases.csv"));
  const test::CommandOutcome other = run_study(kOther, resumed);
  EXPECT_EQ(other.code, 64) << other.output;
  EXPECT_NE(other.output.find("another study"), std::string::npos) << other.output;
}

// SIGINT stops the study within a second, once its first case is done:
// the finished cases are kept (and their table written), and the same
// command then finishes the rest.
TEST(StudyCommand, InterruptedStudyKeepsFinishedCasesAndResumes) {
  const fs::path whole = fresh_dir("uninterrupted"), cut = fresh_dir("interrupted");
  ASSERT_EQ(run_study(kSmall, whole, "--jobs 1").code, 0);
  const std::string run = std::string(UNFURL_BINARY) + " study " + kSmall + " --jobs 1 --quiet --out " + cut.string();
  const test::InterruptedOutcome o =
      test::interrupt_after(run, 0, "ls " + (cut / "cases" / "*" / "case.csv").string() + " >/dev/null 2>&1");
  EXPECT_EQ(o.code, 130) << o.output;
  EXPECT_LT(o.ms_to_end, 1000) << o.output;
  const auto partial = table_without_wall_time(cut / "cases.csv");
  EXPECT_GT(partial.size(), 1u) << o.output;
  EXPECT_LT(partial.size(), 7u) << o.output;
  for (const std::string& row : partial) EXPECT_EQ(row.find("nan"), std::string::npos) << row;
  ASSERT_EQ(run_study(kSmall, cut, "--jobs 1").code, 0);
  EXPECT_EQ(table_without_wall_time(cut / "cases.csv"), table_without_wall_time(whole / "cases.csv"));
}

TEST(StudyCommand, TwoMpiRanksGiveTheSameTableAsOneLocalRun) {
#ifndef UNFURL_WITH_MPI
  GTEST_SKIP() << "built without MPI";
#else
  const fs::path local = fresh_dir("local"), ranks = fresh_dir("mpi");
  ASSERT_EQ(run_study(kSmall, local, "--jobs 1").code, 0);
  const test::CommandOutcome o = test::run_command(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 mpirun -n 2 " +
      std::string(UNFURL_BINARY) + " study " + kSmall + " --quiet --out " + ranks.string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(table_without_wall_time(ranks / "cases.csv"), table_without_wall_time(local / "cases.csv"));
  EXPECT_NE(test::text_of(ranks / "STUDY.md").find("2 processes"), std::string::npos);
#endif
}

// The command's old name still runs a study, and says it was renamed.
TEST(StudyCommand, OldNameSweepStillRunsAndSaysSo) {
  const fs::path out = fresh_dir("old_name");
  const test::CommandOutcome o =
      test::run_command(std::string(UNFURL_BINARY) + " sweep " + kSmall + " --jobs 1 --quiet --out " + out.string());
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("`sweep` is now `unfurl study`"), std::string::npos) << o.output;
  EXPECT_TRUE(fs::exists(out / "cases.csv"));
}

}  // namespace
}  // namespace unfurl
