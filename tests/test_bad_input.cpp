// Hostile and mistaken input: every scene in tests/bad_scenes is refused
// with its exit status and message and leaves no output behind; output
// headers stay parseable by other programs' CSV readers; an interrupted run
// keeps complete files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  std::string file;
  int exit = -1;
  std::string message, args;
};

void PrintTo(const BadInput& bad, std::ostream* out) { *out << bad.file; }

// The header comments of a catalogue file (tests/bad_scenes/README.md).
BadInput read_bad_input(const fs::path& path) {
  BadInput bad;
  bad.file = path.string();
  std::ifstream in(path);
  for (std::string line; std::getline(in, line) && line.rfind("# ", 0) == 0;) {
    if (line.rfind("# exit: ", 0) == 0) bad.exit = std::stoi(line.substr(8));
    if (line.rfind("# message: ", 0) == 0) bad.message = line.substr(11);
    if (line.rfind("# args: ", 0) == 0) bad.args = line.substr(8);
  }
  return bad;
}

std::vector<BadInput> catalogue() {
  std::vector<BadInput> all;
  for (const auto& entry : fs::directory_iterator(std::string(UNFURL_SOURCE_DIR) + "/tests/bad_scenes"))
    if (entry.path().extension() == ".yaml") all.push_back(read_bad_input(entry.path()));
  std::sort(all.begin(), all.end(), [](const BadInput& a, const BadInput& b) { return a.file < b.file; });
  return all;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("unfurl_bad_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  return dir;
}

class BadScene : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadScene, IsRefusedWithItsExitStatusAndMessageAndWritesNothing) {
  const BadInput& bad = GetParam();
  ASSERT_GE(bad.exit, 0) << bad.file << " has no '# exit:' line";
  ASSERT_FALSE(bad.message.empty()) << bad.file << " has no '# message:' line";
  const fs::path out = scratch(fs::path(bad.file).stem().string());
  const test::CommandOutcome o = test::run_command("timeout 20 " + std::string(UNFURL_BINARY) + " simulate " +
                                                   bad.file + " " + bad.args + " --quiet --out " + out.string());
  EXPECT_EQ(o.code, bad.exit) << o.output;
  EXPECT_NE(o.output.find(bad.message), std::string::npos) << "expected '" << bad.message << "' in: " << o.output;
  EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadScene, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<BadInput>& info) {
                           return fs::path(info.param.file).stem().string();
                         });

// Python's csv module reads every header back to the same column names, and
// the names are what pandas keeps as they are: unique, no quotes, a name of
// letters, digits and . _ - and then, in brackets, its unit and frame (no
// comma: the header splits as the rows do).
TEST(OutputFiles, HeadersParseWithPythonsCsvModule) {
  const fs::path out = scratch("headers");
  const std::string unfurl = UNFURL_BINARY;
  ASSERT_EQ(test::run_command(unfurl + " simulate pantograph --t-end 0.2 --quiet --out " + out.string()).code, 0);
  const std::string check =
      "import csv, re, sys\n"
      "for name in sys.argv[1:]:\n"
      "    rows = list(csv.reader(open(name, newline='')))\n"
      "    header = rows[0]\n"
      "    assert len(header) == len(set(header)), name + ': repeated column'\n"
      "    assert all(re.fullmatch(r'[A-Za-z0-9_.-]+( \\[[A-Za-z0-9/^ ;]+\\])?', h) for h in header), name + ': odd "
      "column name'\n"
      "    assert all(len(r) == len(header) for r in rows), name + ': ragged rows'\n"
      "    assert len(header) == open(name).readline().count(',') + 1, name + ': quoted header'\n"
      "print('ok')\n";
  std::ofstream(out / "check.py") << check;
  const test::CommandOutcome o =
      test::run_command("python3 " + (out / "check.py").string() + " " + (out / "trajectory.csv").string() + " " +
                        (out / "loads.csv").string() + " " + (out / "events.csv").string());
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(o.output, "ok\n");
}

// SIGINT ends a long run within a second, with exit status 130 and every
// file complete: parseable, no NaN, the summary saying so.
TEST(Interruption, SigintKeepsCompleteFilesAndSaysWhy) {
  const fs::path out = scratch("sigint");
  const std::string run = std::string(UNFURL_BINARY) + " simulate fourbar --t-end 10000 --sample 0.1 --quiet --out " + out.string();
  const test::InterruptedOutcome o = test::interrupt_after(run, 1.5);
  EXPECT_EQ(o.code, 130) << o.output;
  EXPECT_LT(o.ms_to_end, 1000) << o.output;
  EXPECT_NE(o.output.find("interrupted by SIGINT"), std::string::npos) << o.output;
  for (const char* name : {"trajectory.csv", "loads.csv"}) {
    std::ifstream in(out / name);
    std::string line;
    std::getline(in, line);
    const auto columns = std::count(line.begin(), line.end(), ',');
    long rows = 0;
    while (std::getline(in, line)) {
      ++rows;
      ASSERT_EQ(std::count(line.begin(), line.end(), ','), columns) << name << " row " << rows;
      ASSERT_EQ(line.find("nan"), std::string::npos) << name << " row " << rows;
    }
    EXPECT_GT(rows, 10) << name;
  }
  EXPECT_NE(test::text_of(out / "summary.json").find("\"status\": \"cancelled\""), std::string::npos);
}

// SIGINT after the run, in its summary (a compliant 300-stage array's
// first 0.1 ms: 0.16 s of integration, then about 5 s of torque margins
// and clearance): the summary stops at once, and summary.json has no
// margins or clearance rather than partial ones. (Under a sanitizer the
// signal may find the run still integrating: the same must hold.)
TEST(Interruption, SigintInTheSummaryStopsItAndSaysWhatIsMissing) {
  const fs::path out = scratch("sigint_summary");
  fs::create_directories(out);
  const std::string scene = (out / "array.yaml").string();
  ASSERT_EQ(test::run_command(std::string(UNFURL_BINARY) + " generate pantograph --stages 300 --compliant -o " + scene).code, 0);
  const std::string run = std::string(UNFURL_BINARY) + " simulate " + scene +
                          " --t-end 0.0001 --sample 0.0001 --rtol 1e-7 --atol 1e-9 --quiet --out " + out.string();
  const test::InterruptedOutcome o = test::interrupt_after(run, 1.5);
  EXPECT_EQ(o.code, 130) << o.output;
  EXPECT_LT(o.ms_to_end, 1000) << o.output;
  EXPECT_NE(o.output.find("interrupted by SIGINT"), std::string::npos) << o.output;
  const std::string summary = test::text_of(out / "summary.json");
  EXPECT_NE(summary.find("\"torque_margin\": null"), std::string::npos);
  EXPECT_NE(summary.find("\"clearance\": null"), std::string::npos);
}

}  // namespace
}  // namespace unfurl
