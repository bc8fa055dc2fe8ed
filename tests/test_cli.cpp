// The command line: scene validation (exit code 2 with file, line and
// field), the files `simulate` writes, and --set.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "support.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

using Outcome = test::CommandOutcome;

// unfurl with these arguments.
Outcome run(const std::string& arguments) { return test::run_command(std::string(UNFURL_BINARY) + " " + arguments); }

fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / ("unfurl_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// A valid one-loop scene; the tests break one line of it at a time.
const char* kValidScene = R"(name: tiny
bodies:
  - name: crank
    parent: ground
    mass: 0.5
    inertia: [0.0067, 0.0001, 0.0067]
    joint: {name: a, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, -0.2, 0]}
  - name: coupler
    parent: crank
    mass: 1.5
    inertia: [0.18, 0.0003, 0.18]
    joint: {name: b, type: revolute, axis: [1, 0, 0], parent_point: [0, 0.2, 0], child_point: [0, -0.6, 0]}
  - name: rocker
    parent: ground
    mass: 0.5
    inertia: [0.0267, 0.0001, 0.0267]
    joint: {name: c, type: revolute, axis: [1, 0, 0], parent_point: [0, 1.0, 0], child_point: [0, -0.4, 0]}
  - name: rocker_image
    parent: coupler
    mass: 0.5
    inertia: [0.0267, 0.0001, 0.0267]
    joint: {name: d, type: revolute, axis: [1, 0, 0], parent_point: [0, 0.6, 0], child_point: [0, 0.4, 0]}
base: {name: ground}
loops:
  - {name: rocker, body: rocker, image: rocker_image}
initial:
  q: {a: 1.5707963267948966, b: -1.2411402364746325, c: 1.4007473763557963, d: 1.0710912860355322}
run: {t_end: 0.1}
)";

std::string replace_line(const std::string& text, int line, const std::string& with) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string l;
  for (int n = 1; std::getline(in, l); ++n) out << (n == line ? with : l) << "\n";
  return out.str();
}

struct BadScene {
  const char* name;
  int line;             // the line to replace (1-based)
  const char* with;     // its new text
  int reported_line;    // the line the error must name
  const char* message;  // a regex the message must match
};

class Validation : public ::testing::TestWithParam<BadScene> {};

TEST_P(Validation, ExitsWithCode2AndNamesFileLineAndField) {
  const BadScene& bad = GetParam();
  const fs::path dir = temp_dir();
  const fs::path file = dir / (std::string(bad.name) + ".yaml");
  std::ofstream(file) << replace_line(kValidScene, bad.line, bad.with);
  const Outcome o = run("simulate " + file.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(o.code, 2) << o.output;
  const std::string where = file.string() + ":" + std::to_string(bad.reported_line) + ":";
  EXPECT_NE(o.output.find(where), std::string::npos) << "expected '" << where << "' in: " << o.output;
  EXPECT_TRUE(std::regex_search(o.output, std::regex(bad.message))) << o.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "trajectory.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    SceneErrors, Validation,
    ::testing::Values(
        BadScene{"unknown_key", 5, "    mass: 0.5\n    colour: red", 6, "unknown key 'colour'"},
        BadScene{"wrong_type", 10, "    mass: heavy", 10, "bodies\\[1\\] \\(coupler\\)\\.mass: expected a number"},
        BadScene{"missing_field", 6, "", 3, "bodies\\[0\\] \\(crank\\): missing field 'inertia'"},
        BadScene{"not_regular", 9, "    parent: rocker", 9, "numbering is not regular"},
        BadScene{"inertia_not_pd", 6, "    inertia: [0.0067, -0.0001, 0.0067]", 6, "not positive definite"},
        BadScene{"negative_mass", 5, "    mass: -0.5", 5, "negative mass"},
        BadScene{"loop_open", 27, "  q: {a: 1.6, b: -1.2411402364746325, c: 1.4007473763557963, d: 1.0710912860355322}",
                 25, "loop 'rocker' does not close.*0\\.0[0-9]* m apart"},
        BadScene{"zero_axis", 7,
                 "    joint: {name: a, type: revolute, axis: [0, 0, 0], parent_point: [0, 0, 0], child_point: [0, -0.2, 0]}",
                 7, "zero length"}),
    [](const ::testing::TestParamInfo<BadScene>& info) { return std::string(info.param.name); });

TEST(Cli, ValidSceneRunsAndWritesTheThreeFiles) {
  const fs::path dir = temp_dir();
  const fs::path file = dir / "valid.yaml";
  std::ofstream(file) << kValidScene;
  const Outcome o = run("simulate " + file.string() + " --out " + (dir / "ok").string());
  ASSERT_EQ(o.code, 0) << o.output;
  for (const char* f : {"trajectory.csv", "events.csv", "summary.json"}) EXPECT_TRUE(fs::exists(dir / "ok" / f)) << f;
  std::ifstream csv(dir / "ok" / "trajectory.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "t [s],q.a [rad],dq.a [rad/s],p.a [N m s],q.b [rad],dq.b [rad/s],p.b [N m s],q.c [rad],dq.c [rad/s],"
            "p.c [N m s],q.d [rad],dq.d [rad/s],p.d [N m s],closure_gap.rocker [m],closure_angle.rocker [rad],"
            "energy [J],energy_dissipated [J]");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 11);  // 0, 0.01, ..., 0.1
}

// A tolerance below the right-hand side's round-off is named, with one
// that is as accurate; the pantograph's own tolerance is not.
TEST(Cli, AToleranceBelowTheRoundOffIsNamed) {
  const fs::path dir = temp_dir();
  const std::string warning = "lies below the right-hand side's round-off";
  const Outcome tight = run("simulate pantograph --t-end 0.2 --rtol 1e-11 --out " + (dir / "tight").string());
  ASSERT_EQ(tight.code, 0) << tight.output;
  EXPECT_NE(tight.output.find(warning), std::string::npos) << tight.output;
  EXPECT_NE(tight.output.find("rtol 1e-10 costs fewer"), std::string::npos) << tight.output;
  const Outcome own = run("simulate pantograph --t-end 0.2 --out " + (dir / "own").string());
  ASSERT_EQ(own.code, 0) << own.output;
  EXPECT_EQ(own.output.find(warning), std::string::npos) << own.output;
}

// The libraries the dynamic loader opened for a command (LD_DEBUG=libs).
std::string loaded_libraries(const std::string& arguments) {
  return test::run_command("LD_DEBUG=libs " + std::string(UNFURL_BINARY) + " " + arguments).output;
}

bool loads_gl(const std::string& loader_log) {
  return std::regex_search(loader_log, std::regex(R"(calling init: \S*lib(EGL|GL|GLX|OSMesa|glfw|X11)\.so)"));
}

// simulate, generate and the other text commands load no GL library (it
// cost 20 ms a process); the drawing commands load the graphics module.
TEST(Cli, SimulateLoadsNoGlLibrary) {
  const fs::path dir = temp_dir();
  const std::string simulate = loaded_libraries("simulate pantograph --t-end 0.5 --quiet --out " + (dir / "gl").string());
  ASSERT_NE(simulate.find("calling init"), std::string::npos) << "LD_DEBUG gave nothing to check";
  EXPECT_FALSE(loads_gl(simulate));
  EXPECT_FALSE(loads_gl(loaded_libraries("generate pantograph --stages 4 -o " + (dir / "p4.yaml").string())));
#ifdef UNFURL_WITH_RENDER
  const std::string render = loaded_libraries("render pantograph --from 0 --to 0 --out " + (dir / "frames").string());
  EXPECT_NE(render.find("libunfurl_graphics.so"), std::string::npos);
  EXPECT_TRUE(loads_gl(render));
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00000.png"));
#endif
}

// The z-fold's panels pass through each other and the bus as it unfolds
// (its hinges are not synchronized and nothing stops them): simulate names
// each span, and summary.json has them with the closest pair. Its solids
// are its meshes, which the renderer's reader reads.
#ifdef UNFURL_WITH_RENDER
TEST(Cli, BodiesThatInterpenetrateAreNamed) {
  const fs::path dir = temp_dir();
  const Outcome o = run("simulate zfold --t-end 4 --out " + (dir / "zf").string());
  ASSERT_EQ(o.code, 0) << o.output;
  // The first contact: touching pairs all stand at 0 m, the earliest is named.
  EXPECT_NE(o.output.find("clearance    closest 0 m, frame_A and panel_A2 at t = 0.570000 s"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("warning      frame_A and panel_A2 touch or interpenetrate from t = 0.570000 s to 3.590000 s"),
            std::string::npos)
      << o.output;
  const std::string json = test::text_of(dir / "zf" / "summary.json");
  EXPECT_NE(json.find("\"clearance\": {\n    \"clear\": false"), std::string::npos) << json;
  EXPECT_NE(json.find("\"clearance\": \"distance m, times s\""), std::string::npos) << json;
}
#else
TEST(Cli, WithoutAMeshReaderClearanceSaysSoOnce) {
  const Outcome o = run("simulate zfold --t-end 0.1 --out " + (temp_dir() / "zf").string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("clearance    5 bodies' meshes left out (no mesh reader in this build): declare their "
                          "collision: shapes"),
            std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("warning"), std::string::npos) << o.output;
}
#endif

// A flexible body's largest deflection is a peak of the run (summary.json,
// printed); bent beyond a tenth of its size, where the small-deformation
// model stops holding, simulate says so: zfold_plates' panels at 1/1500 of
// their bending stiffness sag by a third of their 1.2 m and more; as built
// they bend by 4 mm and nothing is said.
TEST(Cli, AFlexibleBodyBentFarBeyondItsModelIsWarnedAbout) {
  const fs::path dir = temp_dir();
  std::string soft;
  for (const char* panel : {"panel_A1", "panel_A2", "panel_A3"})
    soft += std::string(" --set bodies.") + panel + ".flexible.plate.bending_stiffness=5";
  Outcome o = run("simulate zfold_plates --t-end 12" + soft + " --out " + (dir / "soft").string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("peak deflection 0.6711 m at panel_A2"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("warning      panel_A2 deflects 0.671 m at t = 10.0"), std::string::npos) << o.output;
  const std::string json = test::text_of(dir / "soft" / "summary.json");
  EXPECT_NE(json.find("\"peak_deflection\""), std::string::npos) << json;
  o = run("simulate zfold_plates --t-end 12 --out " + (dir / "stiff").string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("peak deflection 0.003987 m at panel_A2"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("deflects"), std::string::npos) << o.output;
}

TEST(Cli, SetOverridesAValueAndRejectsABadOne) {
  const fs::path dir = temp_dir();
  Outcome o = run("simulate zfold --t-end 0.5 --set springs.j1.stiffness=0.2 --out " + (dir / "set").string());
  ASSERT_EQ(o.code, 0) << o.output;
  o = run("simulate zfold --set springs.j1.stiffness=soft --out " + (dir / "bad").string());
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.output.find("--set springs.j1.stiffness=soft"), std::string::npos) << o.output;
}

TEST(Cli, UnknownOptionIsAUsageError) {
  const Outcome o = run("simulate zfold --colour red");
  EXPECT_EQ(o.code, 64);
  EXPECT_NE(o.output.find("unknown option --colour"), std::string::npos);
}

TEST(Cli, HelpDocumentsEveryFlag) {
  const Outcome o = run("simulate --help");
  EXPECT_EQ(o.code, 0);
  for (const char* flag : {"--out", "--t-end", "--integrator", "--rtol", "--atol", "--dt", "--sample", "--set"})
    EXPECT_NE(o.output.find(flag), std::string::npos) << flag;
}

TEST(Cli, GenerateWritesASceneThatSimulates) {
  const fs::path dir = temp_dir();
  const fs::path file = dir / "pantograph_5.yaml";
  ASSERT_EQ(run("generate pantograph --stages 5 -o " + file.string()).code, 0);
  const sim::Scene scene = sim::load_scene_file(file.string());
  EXPECT_EQ(scene.loops.size(), 5u);
  EXPECT_EQ(scene.model.size(), 17);
  const Outcome sim = run("simulate " + file.string() + " --t-end 0.2 --quiet --out " + (dir / "p5").string());
  EXPECT_EQ(sim.code, 0) << sim.output;
  EXPECT_TRUE(fs::exists(dir / "p5" / "summary.json"));
  const Outcome bad = run("generate zfold --panels 0");
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.output.find("--panels"), std::string::npos) << bad.output;
}

TEST(Cli, GenerateWritesAFlexibleArrayAndRefusesMixedOptions) {
  const fs::path dir = temp_dir();
  const fs::path file = dir / "pantograph_flexible_4.yaml";
  ASSERT_EQ(run("generate pantograph --stages 4 --flexible -o " + file.string()).code, 0);
  const sim::Scene scene = sim::load_scene_file(file.string());
  EXPECT_EQ(scene.loops.size(), 4u);
  EXPECT_EQ(scene.model.size(), 4 * 4 + 2);
  const Outcome both = run("generate pantograph --stages 4 --flexible --compliant");
  EXPECT_EQ(both.code, 64);
  EXPECT_NE(both.output.find("two different arrays"), std::string::npos) << both.output;
  const Outcome zfold = run("generate zfold --panels 4 --flexible");
  EXPECT_EQ(zfold.code, 64);
  EXPECT_NE(zfold.output.find("pantograph only"), std::string::npos) << zfold.output;
}

// The compliance suite's quick cases: the compliant pantograph's peak
// hinge force against its pins' stiffness, nominal and off-nominal, and
// the rigid pantograph's; the off-nominal force grows with the stiffness
// (the rigid model has no answer there) while the nominal one stays near
// the rigid 163 N.
TEST(Cli, ComplianceReportTablesTheHingeForceAgainstPinStiffness) {
  const fs::path dir = temp_dir() / "compliance";
  const Outcome o = run("report --suite compliance --quick --quiet --out " + dir.string());
  ASSERT_EQ(o.code, 0) << o.output;
  for (const char* f : {"COMPLIANCE.md", "pin_stiffness.csv"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
#ifdef UNFURL_WITH_RENDER
  EXPECT_TRUE(fs::exists(dir / "pin_stiffness.png"));
#endif
  std::map<std::string, double> peak;  // "deployment model stiffness" -> N
  std::ifstream csv(dir / "pin_stiffness.csv");
  std::string line;
  std::getline(csv, line);
  int rows = 0;
  for (; std::getline(csv, line); ++rows) {
    std::vector<std::string> f;
    std::string field;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) f.push_back(field), field.clear();
      else field += c;
    }
    f.push_back(field);
    ASSERT_GE(f.size(), 6u) << line;
    EXPECT_EQ(f[3], "finished") << line;
    peak[f[0].substr(0, 3) + " " + f[1] + " " + f[2]] = std::stod(f[5]);
  }
  EXPECT_EQ(rows, 8);  // 3 stiffnesses and the rigid model, two deployments
  EXPECT_GT(peak["off compliant 1e+07"], 3 * peak["off compliant 100000"]);
  EXPECT_NEAR(peak["nom compliant 1e+07"], peak["nom rigid "], 0.01 * peak["nom rigid "]);
  EXPECT_NEAR(peak["nom rigid "], 162.76, 0.1);
}

// unfurl modes writes its table and files; render --mode draws a cycle of
// a mode; a mode beyond the scene's is a usage error naming how many.
TEST(Cli, ModesWritesItsFilesAndRenderDrawsAMode) {
  const fs::path dir = temp_dir() / "modes";
  const Outcome o = run("modes zfold --out " + dir.string());
  ASSERT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("0.4131"), std::string::npos) << o.output;
  std::ifstream csv(dir / "modes.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(header,
            "mode,kind,frequency_hz [Hz],damping_ratio,damped_frequency_hz [Hz],shape.j1 [rad],shape.j2 [rad],"
            "shape.j3 [rad],shape.j4 [rad]");
  EXPECT_EQ(row.rfind("1,elastic,0.4131", 0), 0u) << row;
  const std::string json = test::text_of(dir / "modes.json");
  EXPECT_NE(json.find("\"kind\": \"elastic\""), std::string::npos) << json;
  EXPECT_NE(json.find("settled to its static equilibrium"), std::string::npos) << json;
#ifdef UNFURL_WITH_RENDER
  const Outcome drawn = run("render zfold --mode 2 --fps 2 --size 320x180 --quiet --out " + (dir / "frames").string());
  ASSERT_EQ(drawn.code, 0) << drawn.output;
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00004.png"));  // one 2 s cycle at 2 fps: 5 frames
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_00005.png"));
  const Outcome beyond = run("render zfold --mode 9 --out " + (dir / "none").string());
  EXPECT_EQ(beyond.code, 64);
  EXPECT_NE(beyond.output.find("has 4 modes"), std::string::npos) << beyond.output;
#endif
}

// Small frictions: plots without frames draw no frame; an initial angle that
// looks like degrees is warned about; a spring's preload may be a torque at
// an angle (the same spring as its free angle).
TEST(Cli, PlotsWithoutFramesDrawNoFrameAndDegreesAreWarnedAbout) {
  const fs::path dir = temp_dir() / "friction";
#ifdef UNFURL_WITH_RENDER
  const Outcome plots = run("render zfold --plots --no-frames --out " + (dir / "plots").string());
  ASSERT_EQ(plots.code, 0) << plots.output;
  EXPECT_NE(plots.output.find("frames       none drawn"), std::string::npos) << plots.output;
  EXPECT_TRUE(fs::exists(dir / "plots" / "loads.png"));
#endif
  const Outcome degrees = run("simulate zfold --t-end 0.1 --set initial.q.j1=-90 --out " + (dir / "deg").string());
  ASSERT_EQ(degrees.code, 0) << degrees.output;
  EXPECT_NE(degrees.output.find("warning: built-in:zfold: initial.q.j1: -90 rad is more than a turn"),
            std::string::npos)
      << degrees.output;
  const Outcome plain = run("simulate zfold --t-end 0.1 --out " + (dir / "plain").string());
  EXPECT_EQ(plain.output.find("warning"), std::string::npos) << plain.output;
  const sim::Scene as_torque = sim::load_builtin_scene(
      "zfold", {{"springs.j1", "{joint: j1, stiffness: 0.1, preload_torque: 0.3141592653589793, "
                               "preload_angle: -1.5707963267948966, damping: 0.02}"}});
  EXPECT_NEAR(as_torque.elements_of<sim::JointSpring>()[0]->free_position, M_PI / 2, 1e-15);
  EXPECT_NE(test::scene_error(R"(
name: both
bodies:
  - {name: a, parent: base, mass: 1, inertia: [1, 1, 1],
     joint: {name: h, type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}
springs:
  - {joint: h, stiffness: 1, free_position: 0.2, preload_torque: 1, preload_angle: 0}
)")
                .find("springs[0].free_position: give the preload as free_position or as preload_torque"),
            std::string::npos);
}

TEST(Cli, SolverFailureReportsWhereAndKeepsResults) {
  // RK4 with a step far beyond the regulator's stability limit diverges.
  const fs::path dir = temp_dir() / "fail";
  const Outcome o = run("simulate fourbar --integrator rk4 --dt 0.01 --t-end 2 --out " + dir.string());
  EXPECT_EQ(o.code, 1) << o.output;
  EXPECT_TRUE(std::regex_search(o.output, std::regex("check failed at t = [0-9.e-]+ s \\(step"))) << o.output;
  EXPECT_TRUE(fs::exists(dir / "trajectory.csv"));
  EXPECT_NE(test::text_of(dir / "summary.json").find("\"status\": \"failed\""), std::string::npos);
}

}  // namespace
}  // namespace unfurl
