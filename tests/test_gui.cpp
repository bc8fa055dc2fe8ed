// The GUI under Xvfb, driven by a script: it plays, scrubs, changes a
// spring's preload, waits for the new run and takes screenshots read back
// from its framebuffer.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "png_read.hpp"
#include "support.hpp"
#include "gui/file_dialog.hpp"
#include "unfurl/io/video_pipe.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

// A test's scratch directory under /tmp, made empty; removed afterwards
// unless the test failed (its files are then what to look at).
struct Scratch {
  explicit Scratch(const std::string& name)
      : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() {
    if (!::testing::Test::HasFailure()) fs::remove_all(path);
  }
  fs::path path;
};

// Runs `unfurl gui ARGS --script DIR/session.txt` under Xvfb at 1280x800;
// "" when it exits 0, else its log.
std::string gui_session_failure(const fs::path& dir, const std::string& args) {
  const std::string command = "timeout 300 xvfb-run -a -s '-screen 0 1280x800x24' " + std::string(UNFURL_BINARY) +
                              " gui " + args + " --script " + (dir / "session.txt").string() + " > " +
                              (dir / "log.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return "exit status " + std::to_string(status) + ":\n" + test::text_of(dir / "log.txt");
}

// Latch time of `joint` in the report's run `which` ("current"/"previous"):
// inside that run's latch_time object only.
double latch_time(const std::string& report, const std::string& which, const std::string& joint) {
  const auto run = report.find("\"" + which + "\"");
  if (run == std::string::npos) return NAN;
  const auto open = report.find("\"latch_time\": {", run);
  const auto close = report.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return NAN;
  const std::string object = report.substr(open, close - open);
  std::smatch m;
  if (!std::regex_search(object, m, std::regex("\"" + joint + "\": ([0-9.eE+-]+)"))) return NAN;
  return std::stod(m[1]);
}

// Pixels in a region of the screenshot whose colour passes `is`.
template <class Is>
int count_pixels(const render::Image& image, int x0, int y0, int x1, int y1, Is is) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (is(image.pixel(x, y))) ++count;
  return count;
}

// Pixels of the solar cells' blue in a region of the screenshot.
int cell_pixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  return count_pixels(image, x0, y0, x1, y1,
                      [](const std::uint8_t* p) { return p[2] > 70 && p[2] > p[0] + 40 && p[2] > p[1] + 25; });
}

// Bus-yellow pixels in a region of the screenshot.
int bus_pixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  return count_pixels(image, x0, y0, x1, y1,
                      [](const std::uint8_t* p) { return p[0] > 120 && p[1] > 80 && p[2] < 90 && p[0] > p[2] + 60; });
}

TEST(Gui, ScriptedSessionPlaysScrubsChangesAPreloadAndReruns) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "play\n"
                                        "wait 1\n"
                                        "pause\n"
                                        "scrub 6.5\n"
                                        "wait 0.3\n"
                                        "screenshot " << (dir / "first.png").string() << "\n"
                                        "report " << (dir / "first.json").string() << "\n"
                                        "set springs.0.free_position 1.3\n"
                                        "wait 0.2\n"
                                        "screenshot " << (dir / "rerunning.png").string() << "\n"
                                        "wait_run\n"
                                        "scrub 6.5\n"
                                        "wait 0.3\n"
                                        "screenshot " << (dir / "second.png").string() << "\n"
                                        "save_frame " << (dir / "view.png").string() << "\n"
                                        "idle 3\n"
                                        "report " << (dir / "second.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph"), "");

  // Not blank, and the 3D view (top left) shows the array's cells.
  const render::Image shot = test::read_png((dir / "second.png").string());
  ASSERT_EQ(shot.width, 1280);
  std::set<int> colours;
  for (std::size_t k = 0; k < shot.rgb.size(); k += 3)
    colours.insert(shot.rgb[k] << 16 | shot.rgb[k + 1] << 8 | shot.rgb[k + 2]);
  EXPECT_GT(colours.size(), 500u);
  EXPECT_GT(cell_pixels(shot, 0, 60, shot.width * 6 / 10, shot.height / 2), 2000);
  // Save frame draws at the export form's size (1280x720), not the viewport's.
  const render::Image view = test::read_png((dir / "view.png").string());
  EXPECT_EQ(view.width, 1280);
  EXPECT_EQ(view.height, 720);
  EXPECT_GT(cell_pixels(view, 0, 0, view.width, view.height), 2000);

  // The new run differs from the old: chain A's root latch moved.
  const std::string report = test::text_of(dir / "second.json");
  const double before = latch_time(report, "previous", "j1"), after = latch_time(report, "current", "j1");
  ASSERT_FALSE(std::isnan(before)) << report;
  ASSERT_FALSE(std::isnan(after)) << report;
  EXPECT_GT(std::abs(after - before), 1e-3) << report;
  EXPECT_NE(report.find("springs.0.free_position=1.3"), std::string::npos);
  // Idle (nothing playing, computing or moving) it draws on events only: a
  // few frames and a small part of a core in 3 s, not 60 frames a second.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(report, m, std::regex("\"idle_cpu_fraction\": ([0-9.eE+-]+)"))) << report;
  EXPECT_LT(std::stod(m[1]), 0.1) << report;
  ASSERT_TRUE(std::regex_search(report, m, std::regex("\"idle_frames\": ([0-9]+)"))) << report;
  EXPECT_LE(std::stol(m[1]), 10) << report;
  // The first run's report saw one run and no previous.
  EXPECT_TRUE(std::isnan(latch_time(test::text_of(dir / "first.json"), "previous", "j1")));
  std::printf("%s\n", report.c_str());
}

// A flexible plate's parameters edit and re-run like any other: the plate
// z-fold with its first panel four times softer latches otherwise, and its
// panels are drawn bending (the exaggeration slider's value).
TEST(Gui, APlatesBendingStiffnessEditsAndReruns) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_plates");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "exaggerate 30\n"
                                        "set bodies.panel_A1.flexible.plate.bending_stiffness 1858.75\n"
                                        "wait_run\n"
                                        "scrub 8.43\n"
                                        "wait 0.3\n"
                                        "screenshot " << (dir / "bent.png").string() << "\n"
                                        "report " << (dir / "report.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "zfold_plates"), "");
  const std::string report = test::text_of(dir / "report.json");
  EXPECT_NE(report.find("bodies.panel_A1.flexible.plate.bending_stiffness=1858.75"), std::string::npos) << report;
  const double before = latch_time(report, "previous", "j2"), after = latch_time(report, "current", "j2");
  ASSERT_FALSE(std::isnan(before)) << report;
  ASSERT_FALSE(std::isnan(after)) << report;
  EXPECT_GT(std::abs(after - before), 1e-4) << report;
  const render::Image shot = test::read_png((dir / "bent.png").string());
  EXPECT_GT(cell_pixels(shot, 0, 60, shot.width * 6 / 10, shot.height / 2), 2000);
}

// Opening another scene while a run of the first is still going: the old
// run is neither drawn with the new scene's indices nor kept as its ghost
// (it crashed the loop-gap and energy plots).
TEST(Gui, OpeningAnotherSceneDropsThePreviousScenesRuns) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_open");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "plot energy\n"
                                        "set springs.0.free_position 1.0\n"
                                        "open pantograph\n"
                                        "plot loop\n"
                                        "wait 0.3\n"
                                        "plot energy\n"
                                        "wait 0.3\n"
                                        "plot all\n"
                                        "wait_run\n"
                                        "wait 0.3\n"
                                        "report " << (dir / "opened.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "zfold"), "");
  const std::string report = test::text_of(dir / "opened.json");
  EXPECT_FALSE(std::isnan(latch_time(report, "current", "j8"))) << report;  // the pantograph's own run
  EXPECT_TRUE(std::isnan(latch_time(report, "previous", "j1"))) << "the z-fold's run became the ghost: " << report;
}

// A free-floating bus: its attitude plot is a tab of its own, and the
// camera rides with the bus or stays in the inertial frame, where the bus
// is seen turned (zfold_free's turns by about 0.2 rad).
TEST(Gui, AFreeBusHasItsAttitudePlotAndTheCameraRidesWithItOrNot) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_free");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "plot bus\n"
                                        "scrub 18\n"
                                        "wait 0.5\n"
                                        "screenshot " << (dir / "riding.png").string() << "\n"
                                        "camera_frame inertial\n"
                                        "wait 1\n"
                                        "screenshot " << (dir / "inertial.png").string() << "\n"
                                        "report " << (dir / "report.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "zfold_free"), "");
  const std::string report = test::text_of(dir / "report.json");
  EXPECT_NE(report.find("\"plot\": \"bus\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"camera_frame\": \"inertial\""), std::string::npos) << report;
  const render::Image riding = test::read_png((dir / "riding.png").string());
  const render::Image inertial = test::read_png((dir / "inertial.png").string());
  ASSERT_EQ(riding.width, inertial.width);
  // The 3D view: the upper left of the window.
  const int x1 = riding.width * 6 / 10, y1 = riding.height / 2;
  EXPECT_GT(bus_pixels(riding, 0, 60, x1, y1), 2000);
  EXPECT_GT(bus_pixels(inertial, 0, 60, x1, y1), 2000);
  int differing = 0;
  for (int y = 60; y < y1; ++y)
    for (int x = 0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(riding.pixel(x, y)[c] - inertial.pixel(x, y)[c]) > 40) {
          ++differing;
          break;
        }
  std::printf("the inertial view differs from the riding one in %d pixels\n", differing);
  EXPECT_GT(differing, 1000) << "the camera did not leave the bus";
}

// Edits by name, undone and redone, and saved as a scene file that reloads
// to the same run.
TEST(Gui, EditsUndoRedoAndSaveAsAFileThatReloadsToTheSameRun) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_edits");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "set springs.j1.free_position 1.3\n"
                                        "wait_run\n"
                                        "set latches.j3.stiffness 900\n"
                                        "wait_run\n"
                                        "undo\n"
                                        "wait_run\n"
                                        "report " << (dir / "undone.json").string() << "\n"
                                        "redo\n"
                                        "wait_run\n"
                                        "report " << (dir / "redone.json").string() << "\n"
                                        "save_scene " << (dir / "edited.yaml").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph --t-end 9"), "");
  const std::string undone = test::text_of(dir / "undone.json"), redone = test::text_of(dir / "redone.json");
  EXPECT_NE(undone.find("springs.j1.free_position=1.3"), std::string::npos) << undone;
  EXPECT_EQ(undone.find("latches.j3.stiffness"), std::string::npos) << undone;
  EXPECT_NE(redone.find("latches.j3.stiffness=900"), std::string::npos) << redone;
  // The saved file, simulated on its own, latches j1 when the GUI's run did.
  const std::string saved = test::text_of(dir / "edited.yaml");
  EXPECT_NE(saved.find("springs.j1.free_position = 1.3"), std::string::npos) << saved;  // the header
  const test::CommandOutcome run = test::run_command(std::string(UNFURL_BINARY) + " simulate " +
                                                     (dir / "edited.yaml").string() + " --out " + (dir / "run").string());
  ASSERT_EQ(run.code, 0) << run.output;
  std::ifstream events(dir / "run" / "events.csv");
  std::string line;
  double j1 = NAN;
  while (std::getline(events, line))
    if (line.find(",latch,j1") != std::string::npos) j1 = std::stod(line.substr(0, line.find(',')));
  EXPECT_NEAR(j1, latch_time(redone, "current", "j1"), 1e-9) << redone;
}

// A row of the report's comparison table: the current run's figure, then
// each pinned run's (NaN for null).
std::vector<double> comparison_row(const std::string& report, const std::string& figure) {
  std::smatch m;
  const std::regex row("\"figure\": \"" + figure + "\",\\s*\"current\": ([^,\\s]+),\\s*\"pinned\": \\[([^\\]]*)\\]");
  if (!std::regex_search(report, m, row)) return {};
  std::vector<double> values{m[1] == "null" ? NAN : std::stod(m[1])};
  std::stringstream list(m[2].str());
  for (std::string cell; std::getline(list, cell, ',');) {
    cell.erase(std::remove_if(cell.begin(), cell.end(), ::isspace), cell.end());
    if (!cell.empty()) values.push_back(cell == "null" ? NAN : std::stod(cell));
  }
  return values;
}

// A run whose bodies go through each other: the spans the timeline marks
// are the run's own (as `simulate` finds them), and the Runs table gives
// the clearance beside the loads and the torque margin.
TEST(Gui, ContactsAreTheRunsOwnAndTabledWithTheLoads) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_contacts");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "report " << (dir / "report.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "zfold"), "");
  const std::string report = test::text_of(dir / "report.json");
  const test::CommandOutcome run = test::run_command(std::string(UNFURL_BINARY) + " simulate zfold --out " +
                                                     (dir / "run").string());
  ASSERT_EQ(run.code, 0) << run.output;
  // Every contact simulate warns about is in the session's report.
  std::size_t warned = 0;
  const std::regex contact("warning +(\\w+) and (\\w+) touch or interpenetrate from t = ([0-9.]+) s");
  for (std::sregex_iterator it(run.output.begin(), run.output.end(), contact), end; it != end; ++it, ++warned) {
    std::smatch m;
    const std::regex entry("\"body_a\": \"" + (*it)[1].str() + "\",\\s*\"body_b\": \"" + (*it)[2].str() +
                           "\",\\s*\"t_begin\": ([-0-9.e]+)");
    ASSERT_TRUE(std::regex_search(report, m, entry)) << (*it)[0] << "\n" << report;
    EXPECT_NEAR(std::stod(m[1]), std::stod((*it)[3]), 1e-6);
  }
  EXPECT_EQ(warned, 5u) << run.output;
  EXPECT_EQ(comparison_row(report, "clearance, m"), std::vector<double>{0.0}) << report;
  EXPECT_EQ(comparison_row(report, "spans of contact"), std::vector<double>{5.0}) << report;
  ASSERT_EQ(comparison_row(report, "peak hinge force, N").size(), 1u) << report;
  EXPECT_GT(comparison_row(report, "peak hinge force, N")[0], 0.0);
  EXPECT_EQ(comparison_row(report, "torque margin").size(), 1u) << report;
}

// The loads an engineer sizes parts from, in the workbench: the hinge
// forces' and the torque margin's plots are tabs, and the Runs table has a
// sensor's peak as simulate's summary.json gives it.
TEST(Gui, HingeForcesTorqueMarginAndSensorsArePlottedAndTabled) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_loads");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "plot hinge\n"
                                        "report " << (dir / "forces.json").string() << "\n"
                                        "plot torque\n"
                                        "report " << (dir / "margin.json").string() << "\n"
                                        "quit\n";
  const std::string sensor = " --set 'sensors=[{name: tip, body: panel_A3, point: [0, 0.6, 0]}]'";
  ASSERT_EQ(gui_session_failure(dir, "zfold --t-end 5" + sensor), "");
  EXPECT_NE(test::text_of(dir / "forces.json").find("\"plot\": \"hinge forces\""), std::string::npos);
  const std::string report = test::text_of(dir / "margin.json");
  EXPECT_NE(report.find("\"plot\": \"torque margin\""), std::string::npos) << report;
  const test::CommandOutcome run = test::run_command(std::string(UNFURL_BINARY) + " simulate zfold --t-end 5" + sensor +
                                                     " --out " + (dir / "run").string());
  ASSERT_EQ(run.code, 0) << run.output;
  const std::string summary = test::text_of(dir / "run" / "summary.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(summary, m, std::regex("\"peak_acceleration\": \\{\\s*\"tip\": \\{\\s*\"value\": ([-0-9.e]+)")))
      << summary;
  const std::vector<double> peak = comparison_row(report, "peak_acceleration.tip, m/s\\^2");
  ASSERT_EQ(peak.size(), 1u) << report;
  EXPECT_NEAR(peak[0], std::stod(m[1]), 1e-9 * std::abs(peak[0]));
  ASSERT_EQ(comparison_row(report, "torque margin").size(), 1u) << report;
}

// The loads on the 3D view: toggled, they are drawn at the play-head with
// their scale, in the view as saved; off, the view is as before.
TEST(Gui, LoadArrowsAreToggledOnTheView) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_arrows");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "scrub 7.4\n"
                                        "save_frame " << (dir / "off.png").string() << "\n"
                                        "loads on 1.5\n"
                                        "wait 0.3\n"
                                        "save_frame " << (dir / "on.png").string() << "\n"
                                        "report " << (dir / "on.json").string() << "\n"
                                        "loads off\n"
                                        "wait 0.3\n"
                                        "report " << (dir / "off.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph --t-end 8"), "");
  const std::string on = test::text_of(dir / "on.json"), off = test::text_of(dir / "off.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(on, m, std::regex("\"load_arrows\": ([0-9]+)"))) << on;
  EXPECT_GE(std::stoi(m[1]), 8) << on;  // a torque at each of the eight latches, just caught
  EXPECT_NE(on.find("hinge force"), std::string::npos) << on;
  EXPECT_NE(on.find("latch torque"), std::string::npos) << on;
  EXPECT_NE(off.find("\"load_arrows\": 0"), std::string::npos) << off;
  const render::Image a = test::read_png((dir / "off.png").string()), b = test::read_png((dir / "on.png").string());
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  int differ = 0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) differ += std::abs(int(a.rgb[k]) - int(b.rgb[k])) > 40;
  EXPECT_GT(differ, 500);
}

// Pixels of the second pinned run's yellow over the dark plots.
int pinned_yellow_pixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > 150 && p[1] > 120 && p[2] < 90 && p[0] - p[2] > 90 && std::abs(p[0] - p[1]) < 60) ++count;
    }
  return count;
}

// Runs pinned for comparison: each one's figures in the difference table
// are the figures it had as the current run; they are drawn in the plots
// in their colour; zoom and the joint checklist reach the plots; a scene of
// another shape drops them.
TEST(Gui, PinnedRunsAreTabledAndDrawnAgainstTheCurrentRun) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_pins");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "report " << (dir / "first.json").string() << "\n"
                                        "pin file values\n"
                                        "set springs.j1.stiffness 0.12\n"
                                        "wait_run\n"
                                        "report " << (dir / "second.json").string() << "\n"
                                        "pin j1 spring 0.12\n"
                                        "undo\n"
                                        "wait_run\n"
                                        "plot angles\n"
                                        "curves j1 j3\n"
                                        "zoom 7.2 7.6\n"
                                        "wait 0.5\n"
                                        "screenshot " << (dir / "pins.png").string() << "\n"
                                        "report " << (dir / "third.json").string() << "\n"
                                        "unpin 0\n"
                                        "report " << (dir / "unpinned.json").string() << "\n"
                                        "open zfold\n"
                                        "wait_run\n"
                                        "report " << (dir / "other.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph --t-end 9"), "");
  const std::string first = test::text_of(dir / "first.json"), second = test::text_of(dir / "second.json");
  const std::string third = test::text_of(dir / "third.json");
  EXPECT_NE(third.find("\"name\": \"file values\""), std::string::npos) << third;
  EXPECT_NE(third.find("\"name\": \"j1 spring 0.12\""), std::string::npos) << third;
  for (const char* figure : {"deployment time, s", "peak latch torque, N m", "final energy, J", "dissipated, J",
                             "largest gap, m", "latch j1, s", "latch j5, s"}) {
    const std::vector<double> then1 = comparison_row(first, figure), then2 = comparison_row(second, figure);
    const std::vector<double> now = comparison_row(third, figure);
    ASSERT_EQ(now.size(), 3u) << figure << "\n" << third;
    ASSERT_EQ(then1.size(), 1u) << figure << "\n" << first;
    ASSERT_EQ(then2.size(), 2u) << figure << "\n" << second;
    EXPECT_TRUE(std::isfinite(now[0])) << figure;
    EXPECT_DOUBLE_EQ(now[1], then1[0]) << figure;
    EXPECT_DOUBLE_EQ(now[2], then2[0]) << figure;
  }
  // Undone, the current run is the file's again (the same figures as the
  // first pinned run); the run with j1's spring changed deployed later.
  const std::vector<double> deployment = comparison_row(third, "deployment time, s");
  EXPECT_DOUBLE_EQ(deployment[0], deployment[1]);
  EXPECT_GT(deployment[2], deployment[0] + 0.1);
  EXPECT_TRUE(std::regex_search(third, std::regex("\"time_zoom\": \\[\\s*7.2,\\s*7.6\\s*\\]"))) << third;
  EXPECT_TRUE(std::regex_search(third, std::regex("\"plot_curves\": \\[\\s*\"j1\",\\s*\"j3\"\\s*\\]"))) << third;
  // The yellow of the second pinned run is in the plot panel (bottom left).
  const render::Image shot = test::read_png((dir / "pins.png").string());
  EXPECT_GT(pinned_yellow_pixels(shot, 0, shot.height * 2 / 3, shot.width * 6 / 10, shot.height - 40), 50);
  const std::string unpinned = test::text_of(dir / "unpinned.json"), other = test::text_of(dir / "other.json");
  EXPECT_EQ(unpinned.find("\"name\": \"file values\""), std::string::npos) << unpinned;
  EXPECT_EQ(comparison_row(unpinned, "final energy, J").size(), 2u) << unpinned;
  EXPECT_TRUE(std::regex_search(other, std::regex("\"pinned\": \\[\\s*\\]"))) << "another scene's pins were kept: " << other;
}

// A screenshot right after a command shows what the command asked for (a
// frame is drawn between them), not the frame before it.
TEST(Gui, AScreenshotShowsWhatTheCommandsBeforeItAskedFor) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_shot");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "plot angles\n"
                                        "wait 0.5\n"
                                        "screenshot " << (dir / "a.png").string() << "\n"
                                        "plot energy\n"
                                        "screenshot " << (dir / "b.png").string() << "\n"
                                        "scrub 19\n"
                                        "save_frame " << (dir / "c.png").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "zfold"), "");
  const render::Image a = test::read_png((dir / "a.png").string()), b = test::read_png((dir / "b.png").string());
  // The plot panel (bottom left) changed from the angles to the energy.
  int differ = 0;
  for (int y = a.height * 2 / 3; y < a.height - 40; ++y)
    for (int x = 0; x < a.width * 6 / 10; ++x)
      if (std::abs(int(a.pixel(x, y)[0]) - int(b.pixel(x, y)[0])) > 40) ++differ;
  EXPECT_GT(differ, 1000);
  // The view at t = 19 shows the deployed wing: the cells' blue, not the
  // stowed stack at t = 0.
  const render::Image c = test::read_png((dir / "c.png").string());
  EXPECT_GT(cell_pixels(c, 0, 0, c.width, c.height), 2000);
}

// The Modes tab: the finished run's modes (the compliant pantograph's first
// at 0.413 Hz, as `unfurl modes` gives), one of them animated in the view:
// the view moves between two moments of the cycle with the play-head
// still, and a new run stops the animation.
TEST(Gui, TheModesTabAnimatesAModeOfTheDeployedArray) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_modes");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "modes\n"
                                        "wait 0.2\n"
                                        "mode 1\n"
                                        "wait 0.3\n"
                                        "save_frame " << (dir / "a.png").string() << "\n"
                                        "wait 1.0\n"
                                        "save_frame " << (dir / "b.png").string() << "\n"
                                        "report " << (dir / "shown.json").string() << "\n"
                                        "set springs.j1.stiffness 0.12\n"
                                        "wait_run\n"
                                        "report " << (dir / "rerun.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph_compliant --t-end 12"), "");
  const std::string shown = test::text_of(dir / "shown.json"), rerun = test::text_of(dir / "rerun.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(shown, m, std::regex("\"modes_hz\": \\[\\s*([0-9.eE+-]+)"))) << shown;
  EXPECT_NEAR(std::stod(m[1]), 0.41315, 1e-4);
  EXPECT_NE(shown.find("\"mode_shown\": 1"), std::string::npos) << shown;
  EXPECT_NE(rerun.find("\"mode_shown\": 0"), std::string::npos) << rerun;
  // Half a cycle apart (of the 2 s drawn cycle), the array is bent the
  // other way: the two frames differ.
  const render::Image a = test::read_png((dir / "a.png").string()), b = test::read_png((dir / "b.png").string());
  ASSERT_EQ(a.width, b.width);
  int differ = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (std::abs(int(a.pixel(x, y)[2]) - int(b.pixel(x, y)[2])) > 40) ++differ;
  EXPECT_GT(differ, 500);
}

// A finished study in the workbench: the Study tab lists its cases; picking
// one (here by the script, as a click does) re-runs that case, whose latch
// times are the study's own for it; a failure case (a latch removed) then
// loads with the case shown before as its ghost.
TEST(Gui, StudyCasesOpenFromTheStudyTab) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_study");
  const fs::path& dir = scratch.path;
  const std::string study = std::string(UNFURL_SOURCE_DIR) + "/tests/studies/small_monte_carlo.yaml";
  const test::CommandOutcome sweep =
      test::run_command(std::string(UNFURL_BINARY) + " study " + study + " --out " + (dir / "study").string() + " --quiet");
  ASSERT_EQ(sweep.code, 0) << sweep.output;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "report " << (dir / "nominal.json").string() << "\n"
                                        "pin nominal\n"
                                        "case case-0003\n"
                                        "wait_run\n"
                                        "scrub 8\n"
                                        "wait 0.3\n"
                                        "screenshot " << (dir / "case.png").string() << "\n"
                                        "report " << (dir / "case.json").string() << "\n"
                                        "case fail-latch-j3-fails\n"
                                        "wait_run\n"
                                        "report " << (dir / "failure.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "--study " + study + " --out " + (dir / "study").string()), "");

  const std::string nominal = test::text_of(dir / "nominal.json"), shown = test::text_of(dir / "case.json");
  EXPECT_NE(nominal.find("\"study_case\": \"nominal\""), std::string::npos) << nominal;
  EXPECT_NE(shown.find("\"study_case\": \"case-0003\""), std::string::npos) << shown;
  EXPECT_NE(shown.find("\"study_rows\": 6"), std::string::npos) << shown;
  // The case's latch time of j1, as the sweep recorded it in cases.csv
  // (whose ids and numbers hold no commas).
  const auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
    return out;
  };
  std::ifstream cases(dir / "study" / "cases.csv");
  std::string line, j1_time;
  std::getline(cases, line);
  const std::vector<std::string> header = cells(line);
  // The column's name precedes its unit, "latch_time.j1 [s]".
  const std::size_t column = std::find(header.begin(), header.end(), "latch_time.j1 [s]") - header.begin();
  while (std::getline(cases, line))
    if (line.rfind("case-0003,", 0) == 0 && cells(line).size() > column) j1_time = cells(line)[column];
  ASSERT_FALSE(j1_time.empty());
  EXPECT_NEAR(latch_time(shown, "current", "j1"), std::stod(j1_time), 1e-9) << shown;
  EXPECT_FALSE(std::isnan(latch_time(shown, "previous", "j1"))) << "the nominal case is the ghost: " << shown;
  const std::string failure = test::text_of(dir / "failure.json");
  EXPECT_NE(failure.find("\"study_case\": \"fail-latch-j3-fails\""), std::string::npos) << failure;
  EXPECT_TRUE(std::isnan(latch_time(failure, "current", "j3"))) << failure;
  // The case shown before stays as the ghost, though this one has a latch
  // fewer (the plots draw joints, which both have).
  EXPECT_FALSE(std::isnan(latch_time(failure, "previous", "j1"))) << "the previous case's ghost was dropped";
  // The nominal case, pinned, is tabled beside the failure case: its
  // figures as they were when it was the current run.
  for (const char* figure : {"deployment time, s", "peak latch torque, N m", "peak hinge force, N", "torque margin"}) {
    const std::vector<double> row = comparison_row(failure, figure), then = comparison_row(nominal, figure);
    ASSERT_EQ(row.size(), 2u) << figure << "\n" << failure;
    ASSERT_EQ(then.size(), 1u) << figure << "\n" << nominal;
    EXPECT_EQ(row[1], then[0]) << figure;
  }
  EXPECT_TRUE(std::isnan(comparison_row(failure, "deployment time, s")[0])) << "a latch never engaged: not deployed";
  const render::Image shot = test::read_png((dir / "case.png").string());
  EXPECT_GT(cell_pixels(shot, 0, 60, shot.width * 6 / 10, shot.height / 2), 2000);
}

// What a failure case put into its scene (an added friction, a stuck
// hinge's stop, here latches.8 beside j2's own latch, a broken spring) is
// the study file's: an edit of it is refused with a message (it used to fail to load, or be undone by the
// failure), while the case's other parameters stay editable.
TEST(Gui, AFailureCasesInjectedElementsAreReadOnly) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  const Scratch scratch("unfurl_gui_failure");
  const fs::path& dir = scratch.path;
  const std::string study = std::string(UNFURL_SOURCE_DIR) + "/tests/studies/gui_failures.yaml";
  const test::CommandOutcome sweep =
      test::run_command(std::string(UNFURL_BINARY) + " study " + study + " --out " + (dir / "study").string() + " --quiet");
  ASSERT_EQ(sweep.code, 0) << sweep.output;
  std::ofstream(dir / "session.txt") << "case fail-hinge-j4-friction-0.05Nm\n"
                                        "wait_run\n"
                                        "set friction.j4.coulomb 0.2\n"
                                        "report " << (dir / "friction.json").string() << "\n"
                                        "case fail-hinge-j2-stuck\n"
                                        "wait_run\n"
                                        "set stops.0.stiffness 5\n"
                                        "report " << (dir / "stuck.json").string() << "\n"
                                        "case fail-spring-j1-breaks\n"
                                        "wait_run\n"
                                        "set springs.j1.stiffness 1\n"
                                        "report " << (dir / "spring.json").string() << "\n"
                                        "set latches.j3.stiffness 900\n"
                                        "wait_run\n"
                                        "report " << (dir / "other.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "--study " + study + " --out " + (dir / "study").string()), "");
  const std::regex no_edits("\"edits\": \\[\\s*\\]");
  for (const auto& [file, element] : {std::pair{"friction.json", "friction.j4"}, std::pair{"stuck.json", "stops.0"},
                                      std::pair{"spring.json", "springs.j1"}}) {
    const std::string report = test::text_of(dir / file);
    EXPECT_NE(report.find("belongs to the case's failure"), std::string::npos) << report;
    EXPECT_NE(report.find("\"" + std::string(element) + "\""), std::string::npos) << report;  // failure_elements
    EXPECT_TRUE(std::regex_search(report, no_edits)) << report;
  }
  const std::string other = test::text_of(dir / "other.json");
  EXPECT_NE(other.find("latches.j3.stiffness=900"), std::string::npos) << other;
  EXPECT_NE(other.find("\"study_case\": \"fail-spring-j1-breaks\""), std::string::npos) << other;
}

// A long export can be cancelled: the frames written so far stay, each
// complete, and no video (finished or partial) is left behind.
TEST(Gui, ALongExportCancelsAndLeavesNoPartialVideo) {
  if (!io::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
  if (!io::on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  const Scratch scratch("unfurl_gui_cancel");
  const fs::path& dir = scratch.path;
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "export " << (dir / "frames").string() << " 0 9 60 "
                                     << (dir / "frames" / "deployment.mp4").string() << "\n"
                                        "wait 1\n"
                                        "cancel_export\n"
                                        "wait_export\n"
                                        "report " << (dir / "report.json").string() << "\n"
                                        "quit\n";
  ASSERT_EQ(gui_session_failure(dir, "pantograph --t-end 9"), "");
  const std::string report = test::text_of(dir / "report.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(report, m, std::regex("export cancelled after ([0-9]+) of 541 frames"))) << report;
  const long written = std::stol(m[1]);
  EXPECT_LT(written, 541);
  long frames = 0;
  for (const auto& entry : fs::directory_iterator(dir / "frames")) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.rfind("deployment", 0), std::string::npos) << "a video was left: " << name;
    if (name.rfind("frame_", 0) == 0) {
      ++frames;
      EXPECT_EQ(test::read_png(entry.path().string()).width, 1280) << name;  // complete, readable
    }
  }
  EXPECT_EQ(frames, written);
}

// The file dialog's listing: folders first, then the wanted files, each
// sorted; hidden entries and other extensions left out.
TEST(FileDialog, ListsFoldersThenTheWantedFiles) {
  const Scratch scratch("unfurl_dialog");
  const fs::path& dir = scratch.path;
  fs::create_directories(dir / "zeta");
  fs::create_directories(dir / "alpha");
  fs::create_directories(dir / ".git");
  for (const char* name : {"b.yaml", "a.yml", "c.txt", ".hidden.yaml"}) std::ofstream(dir / name) << "x";
  std::vector<std::string> listed;
  for (const app::DirectoryEntry& e : app::directory_entries(dir, {".yaml", ".yml"}))
    listed.push_back(e.name + (e.directory ? "/" : ""));
  EXPECT_EQ(listed, (std::vector<std::string>{"alpha/", "zeta/", "a.yml", "b.yaml"}));
  EXPECT_EQ(app::directory_entries(dir, {}).size(), 5u);  // every file but the hidden one
  EXPECT_THROW(app::directory_entries(dir / "missing", {}), fs::filesystem_error);
}

// Opening a scene through the file dialog with real keyboard events
// (xdotool): the dialog opens in the scene's folder with the name field
// focused; typing a file name and Enter opens it.
TEST(Gui, TheFileDialogOpensASceneTypedWithTheKeyboard) {
  if (!io::on_path("xvfb-run") || !io::on_path("xdotool")) GTEST_SKIP() << "needs xvfb-run and xdotool";
  const Scratch scratch("unfurl_gui_dialog");
  const fs::path& dir = scratch.path;
  const fs::path scenes = fs::path(UNFURL_SOURCE_DIR) / "assets" / "scenes";
  fs::copy_file(scenes / "pendulum.yaml", dir / "pendulum.yaml");
  fs::copy_file(scenes / "fourbar.yaml", dir / "fourbar.yaml");
  std::ofstream(dir / "session.txt") << "wait_run\n"
                                        "browse open\n"
                                        "wait 6\n"
                                        "wait_run\n"
                                        "report " << (dir / "report.json").string() << "\n"
                                        "quit\n";
  // Enter is held for a moment: Dear ImGui 1.86 reads keys as states once a
  // frame, and xdotool's press and release would land in one frame.
  std::ofstream(dir / "keys.sh") << std::string(UNFURL_BINARY) << " gui " << (dir / "pendulum.yaml").string()
                                 << " --script " << (dir / "session.txt").string() << " & pid=$!\n"
                                 << "w=$(xdotool search --sync --name '^unfurl$' | head -1)\n"
                                    "sleep 2\n"
                                    "xdotool windowfocus --sync $w\n"
                                    "xdotool type --delay 30 fourbar.yaml\n"
                                    "xdotool keydown Return; sleep 0.2; xdotool keyup Return\n"
                                    "wait $pid\n";
  const std::string command = "cd " + dir.string() + " && timeout 120 xvfb-run -a -s '-screen 0 1280x800x24' sh " +
                              (dir / "keys.sh").string() + " > " + (dir / "log.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << test::text_of(dir / "log.txt");
  const std::string report = test::text_of(dir / "report.json");
  EXPECT_NE(report.find("\"scene\": \"fourbar\""), std::string::npos) << report;
}

}  // namespace
}  // namespace unfurl
