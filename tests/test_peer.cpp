// Peer tests against MuJoCo: each scene exported by `unfurl export mjcf`,
// run by MuJoCo (RK4 at a small fixed step, the latches applied through its
// passive-force callback by tests/peer/mujoco_peer.cpp) and by unfurl at a
// tight tolerance, compared sample by sample. A failure says where the two
// first part.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "unfurl/render/gl_context.hpp"
#include "unfurl/render/plot_renderer.hpp"
#include "unfurl/io/png_file.hpp"
#include "unfurl/sim/summary.hpp"
#include "support.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

using Outcome = test::CommandOutcome;
const auto run = test::run_command;

fs::path work_dir() {
  const fs::path dir = fs::temp_directory_path() / ("unfurl_peer_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// A CSV of numbers with a header row.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name) return static_cast<int>(c);
    return -1;
  }
};

Table read_csv(const fs::path& path) {
  Table t;
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  for (std::stringstream s(line); std::getline(s, cell, ',');) t.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::stringstream s(line); std::getline(s, cell, ',');) row.push_back(std::atof(cell.c_str()));
    t.rows.push_back(row);
  }
  return t;
}

struct Peer {
  Table angles;                         // t, q.JOINT..., energy
  std::map<std::string, double> latch;  // joint -> time
};

// The scene exported and run by MuJoCo with RK4 at dt.
Peer run_mujoco(const std::string& scene, const std::vector<sim::Override>& overrides, double t_end, double dt,
                double sample) {
  const fs::path dir = work_dir();
  const fs::path xml = dir / (scene + ".xml"), prefix = dir / scene;
  std::string command = std::string(UNFURL_BINARY) + " export mjcf " + scene + " -o " + xml.string();
  for (const sim::Override& o : overrides)
    command += " --set '" + o.path + "=" + o.value + "'";  // values may hold spaces
  const Outcome exported = run(command);
  EXPECT_EQ(exported.code, 0) << exported.output;
  char args[256];
  std::snprintf(args, sizeof args, " %.17g %.17g %.17g ", t_end, dt, sample);
  const Outcome peer = run(std::string(UNFURL_MUJOCO_PEER) + " " + xml.string() + args + prefix.string());
  EXPECT_EQ(peer.code, 0) << peer.output;
  Peer p;
  p.angles = read_csv(prefix.string() + ".csv");
  std::ifstream events(prefix.string() + "_events.csv");
  std::string line;
  std::getline(events, line);
  while (std::getline(events, line)) {
    const auto comma = line.find(',');
    p.latch[line.substr(comma + 1)] = std::atof(line.substr(0, comma).c_str());
  }
  return p;
}

sim::RunResult run_unfurl(const std::string& scene_name, std::vector<sim::Override> overrides, double t_end,
                          double sample) {
  overrides.push_back({"run.t_end", std::to_string(t_end)});
  overrides.push_back({"run.sample", std::to_string(sample)});
  // ERK at a tight tolerance: more accurate than BDF on these smooth runs
  // (and ten times faster here).
  overrides.push_back({"run.integrator", "arkode-erk"});
  overrides.push_back({"run.rtol", "1e-12"});
  overrides.push_back({"run.atol", "1e-12"});
  const sim::Scene scene = sim::load_builtin_scene(scene_name, overrides);
  return sim::simulate(scene, scene.run);
}

// The largest angle difference over the samples with t <= until, and where
// the two first differ by more than `bound`.
struct Comparison {
  double largest = 0;
  std::string first_parting;  // empty if they never part by more than the bound
};

Comparison compare_angles(const sim::Scene& scene, const sim::RunResult& ours, const Peer& peer, double until,
                          double bound) {
  Comparison c;
  const Table& theirs = peer.angles;
  const std::size_t n = std::min(ours.trajectory.samples.size(), theirs.rows.size());
  for (std::size_t k = 0; k < n; ++k) {
    const sim::Sample& s = ours.trajectory.samples[k];
    if (s.t > until + 1e-9) break;
    EXPECT_NEAR(theirs.rows[k][0], s.t, 1e-9) << "sample times differ";
    for (std::size_t col = 1; col + 1 < theirs.columns.size(); ++col) {
      const std::string joint = theirs.columns[col].substr(2);
      const double a = test::q_of(scene, s, joint), b = theirs.rows[k][col];
      const double d = std::abs(a - b);
      c.largest = std::max(c.largest, d);
      if (d > bound && c.first_parting.empty()) {
        std::ostringstream where;
        where.precision(10);
        where << "at t = " << s.t << " s joint " << joint << ": unfurl " << a << ", MuJoCo " << b << " rad";
        c.first_parting = where.str();
      }
    }
  }
  return c;
}

double latch_time_difference(const sim::Scene& scene, const sim::RunResult& ours, const Peer& peer) {
  double worst = 0;
  for (const sim::LatchEvent& e : ours.trajectory.events) {
    const std::string& joint = scene.model.joints[e.joint].name;
    const auto theirs = peer.latch.find(joint);
    if (theirs == peer.latch.end()) {
      ADD_FAILURE() << "MuJoCo never latched " << joint;
      continue;
    }
    worst = std::max(worst, std::abs(e.t - theirs->second));
  }
  EXPECT_EQ(ours.trajectory.events.size(), peer.latch.size());
  return worst;
}

double first_latch(const sim::RunResult& run) {
  double t = INFINITY;
  for (const sim::LatchEvent& e : run.trajectory.events) t = std::min(t, e.t);
  return t;
}

// Runs a scene in both engines and checks the angles (up to the first latch
// and over the whole run) and the latch times against the stated bounds.
struct Bounds {
  double until_first_latch = 0, whole_run = 0, latch_time = 0;
};

void expect_agreement(const std::string& name, const std::vector<sim::Override>& overrides, double t_end, double dt,
                      const Bounds& bounds) {
  const Peer peer = run_mujoco(name, overrides, t_end, dt, 0.01);
  const sim::Scene scene = sim::load_builtin_scene(name, overrides);
  const sim::RunResult ours = run_unfurl(name, overrides, t_end, 0.01);
  ASSERT_EQ(ours.status, sim::RunStatus::finished) << sim::describe(ours.failure);
  ASSERT_EQ(peer.angles.rows.size(), ours.trajectory.samples.size());
  const double first = std::min(first_latch(ours), t_end);
  const Comparison before = compare_angles(scene, ours, peer, first, bounds.until_first_latch);
  const Comparison whole = compare_angles(scene, ours, peer, t_end, bounds.whole_run);
  std::printf("%s: largest angle difference %.3g rad up to t = %g s, %.3g rad over the whole run\n", name.c_str(),
              before.largest, first, whole.largest);
  EXPECT_LT(before.largest, bounds.until_first_latch) << "the two part " << before.first_parting;
  EXPECT_LT(whole.largest, bounds.whole_run) << "the two part " << whole.first_parting;
  if (!scene.latches().empty()) {
    const double latch = latch_time_difference(scene, ours, peer);
    std::printf("%s: latch times differ by at most %.3g s\n", name.c_str(), latch);
    EXPECT_LT(latch, bounds.latch_time);
  }
}

TEST(Peer, PendulumAgreesToRoundOff) { expect_agreement("pendulum", {}, 10, 1e-4, {1e-9, 1e-9, 0}); }

TEST(Peer, DoublePendulumAgreesOverItsFirstSecond) {
  // A chaotic system: only its first second is compared.
  expect_agreement("double_pendulum", {}, 1, 1e-4, {1e-9, 1e-9, 0});
}

TEST(Peer, PointSpringAndViscousFrictionAgree) {
  // A spring-damper from the base to the lower rod's tip (a spatial tendon
  // between two sites in MJCF) and viscous hinge friction (MJCF damping).
  expect_agreement("double_pendulum",
                   {{"point_springs", "[{name: stay, body_a: ground, point_a: [0, 1.2, 0.4], body_b: lower, "
                                      "point_b: [0, 0, -1.0], stiffness: 60, rest_length: 1.2, damping: 0.5}]"},
                    {"friction", "[{joint: shoulder, viscous: 0.3}]"}},
                   2, 1e-4, {1e-9, 1e-9, 0});
}

TEST(Peer, ZfoldAgreesThroughEveryLatch) { expect_agreement("zfold", {}, 20, 1e-4, {1e-8, 1e-8, 1e-8}); }

// The z-fold with a limit that catches its first panel hinge on the way
// out and throws it back: the limit exported as MuJoCo's joint range and
// unfurl's law (limit:j2), which the runner applies in its place.
// Undamped, the limit's torque is continuous and the two agree as closely
// as without it (measured 3.0e-10 rad over the run).
TEST(Peer, ZfoldAgreesAgainstAJointLimit) {
  expect_agreement("zfold", {{"limits", "[{joint: j2, lower: 0.6, stiffness: 20, damping: 0}]"}}, 20, 1e-4,
                   {1e-8, 1e-8, 1e-8});
}

// Damped, its torque jumps by c q' where the joint reaches the end, which
// MuJoCo's fixed RK4 steps straddle at first order in dt (unfurl's error
// control shrinks its steps there): the two part by 3.2e-7 rad at dt 1e-4
// and 6.8e-8 at 2.5e-5 (measured), MuJoCo closing in on unfurl as dt.
TEST(Peer, ZfoldAgainstADampedLimitMujocoConvergesOnUnfurl) {
  const std::vector<sim::Override> limit = {
      {"limits", "[{joint: j2, lower: 0.6, stiffness: 20, damping: 0.2}]"}};
  expect_agreement("zfold", limit, 20, 1e-4, {1e-8, 6e-7, 2e-7});
  expect_agreement("zfold", limit, 20, 2.5e-5, {1e-8, 1.5e-7, 5e-8});
}

// The z-fold on compliant hinges (joint.hpp), exported as three slides and
// two hinges with their springs before each hinge: the pins' coordinates
// and the hinge angles, through every latch.
TEST(Peer, ZfoldOnCompliantHingesAgrees) {
  std::vector<sim::Override> pins;
  for (const char* body : {"frame_A", "panel_A1", "panel_A2", "panel_A3"})
    pins.push_back({std::string("bodies.") + body + ".joint.compliance",
                    "{radial: 1.0e5, axial: 2.0e5, tilt: 1.0e4, radial_damping: 100, axial_damping: 100, "
                    "tilt_damping: 3}"});
  expect_agreement("zfold", pins, 10, 5e-5, {1e-9, 1e-9, 1e-9});  // measured 3.8e-12, 8.0e-11 rad, 1.4e-10 s
}

// The z-fold on a free-floating bus, exported with a free joint: the bus's
// position and attitude quaternion and the joint angles, through every latch.
TEST(Peer, FreeZfoldAgreesOnTheBusAndThroughEveryLatch) {
  expect_agreement("zfold_free", {}, 20, 1e-4, {1e-8, 1e-8, 1e-8});
}

// Ball, universal and planar joints (MJCF ball; two hinges in one body;
// two slides and a hinge) under gravity, the boom spinning, the puck
// sliding on its tether (a point spring: a spatial tendon). MuJoCo's difference from unfurl (ERK, rtol 1e-13) falls as
// dt^2 here (2.2e-8, 5.4e-9, 1.3e-9 rad or m over 1 s at dt 1e-4, 5e-5,
// 2.5e-5): its own error, shrinking towards unfurl's answer.
TEST(Peer, BallPendulumAgrees) { expect_agreement("ball_pendulum", {}, 1, 2.5e-5, {1e-8, 1e-8, 0}); }

TEST(Peer, PantographAgreesToMujocosOwnConstraintError) {
  // unfurl closes the loops with the regulator at v_max = 2000 and its
  // feedforward (3.5e-9 rad from the one-degree-of-freedom reduction before
  // the latches), MuJoCo with stiff point constraints; measured: 7.8e-10 rad
  // apart before the latches, latch times 3.2e-10 s apart. After the latches
  // the array sits at the deployed branch point, where exact runs can part
  // (METHOD.md); here they held within 2.8e-9 rad.
  expect_agreement("pantograph", {}, 20, 1e-5, {1e-8, 1e-6, 1e-8});
}

TEST(Export, EveryBuiltInSceneLoadsAndRunsInMujocoWithoutWarnings) {
  for (const std::string& name : sim::builtin_scene_names()) {
    const Peer peer = run_mujoco(name, {}, 0.05, 1e-4, 0.01);
    EXPECT_EQ(peer.angles.rows.size(), 6u) << name;
  }
}

// MuJoCo's parser stops at a nesting depth: the exporter warns exactly
// where MuJoCo refuses (a generated 95-stage pantograph loads, 96 does not).
TEST(Export, WarnsWhereMujocosParserStopsAndOnlyThere) {
  const fs::path dir = work_dir();
  for (const int stages : {95, 96}) {
    const std::string scene = (dir / ("p" + std::to_string(stages) + ".yaml")).string();
    const std::string xml = (dir / ("p" + std::to_string(stages) + ".xml")).string();
    ASSERT_EQ(run(std::string(UNFURL_BINARY) + " generate pantograph --stages " + std::to_string(stages) + " -o " + scene).code, 0);
    const Outcome exported = run(std::string(UNFURL_BINARY) + " export mjcf " + scene + " -o " + xml);
    ASSERT_EQ(exported.code, 0) << exported.output;
    const bool warned = exported.output.find("MuJoCo will not load this file") != std::string::npos;
    const Outcome loaded = run(std::string(UNFURL_MUJOCO_PEER) + " " + xml + " 0.001 0.001 0.001 " +
                               (dir / ("p" + std::to_string(stages))).string());
    EXPECT_EQ(warned, stages == 96) << exported.output;
    EXPECT_EQ(loaded.code == 0, stages == 95) << loaded.output;
  }
}

TEST(Export, ListsWhatMjcfCannotSay) {
  const Outcome o = run(std::string(UNFURL_BINARY) + " export mjcf pantograph -o " + (work_dir() / "p.xml").string());
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.output.find("not in the MJCF model: the latch of 'j1'"), std::string::npos) << o.output;
  std::ifstream xml(work_dir() / "p.xml");
  const std::string text((std::istreambuf_iterator<char>(xml)), {});
  EXPECT_NE(text.find("<numeric name=\"latch:j8\""), std::string::npos);
  EXPECT_NE(text.find("<connect name=\"A3\""), std::string::npos);
  EXPECT_EQ(text.find("image_A1\" pos"), std::string::npos) << "images are merged, not bodies of their own";
}

TEST(Peer, ZfoldEnergyOfBothEnginesOnOnePlot) {
  // Written where UNFURL_PEER_OUT says (scripts/reports: docs/peer).
  const Peer peer = run_mujoco("zfold", {}, 20, 1e-4, 0.01);
  const sim::RunResult ours = run_unfurl("zfold", {}, 20, 0.01);
  render::PlotSpec spec;
  spec.title = "zfold: energy, unfurl and MuJoCo";
  spec.y_label = "kinetic + springs + latches, J";
  spec.x_label = "time, s";
  render::Series a, b;
  a.label = "unfurl";
  a.color = render::palette(0);
  b.label = "MuJoCo (RK4, dt = 1e-4 s), under unfurl's curve";
  b.color = render::palette(3);
  b.ghost = false;
  double largest = 0;
  const int energy = peer.angles.column("energy");
  ASSERT_GE(energy, 0);
  ASSERT_EQ(peer.angles.rows.size(), ours.trajectory.samples.size());
  for (std::size_t k = 0; k < ours.trajectory.samples.size(); ++k) {
    const sim::Sample& s = ours.trajectory.samples[k];
    a.x.push_back(s.t);
    a.y.push_back(s.energy.total());
    b.x.push_back(peer.angles.rows[k][0]);
    b.y.push_back(peer.angles.rows[k][energy]);
    largest = std::max(largest, std::abs(a.y.back() - b.y.back()));
  }
  spec.series = {b, a};
  for (const sim::LatchEvent& e : ours.trajectory.events) spec.events.push_back(e.t);
  EXPECT_LT(largest, 1e-6) << "the two engines' energies differ";
  const char* out = std::getenv("UNFURL_PEER_OUT");
  const fs::path dir = out ? fs::path(out) : work_dir();
  fs::create_directories(dir);
  auto context = render::make_offscreen_context();
  render::PlotRenderer plotter(1280, 720);
  render::Image image;
  plotter.draw(spec, image);
  io::write_png(image, (dir / "zfold_energy.png").string(), 6);
  render::PlotSpec difference;
  difference.title = "zfold: energy difference between unfurl and MuJoCo";
  difference.y_label = "|E_unfurl - E_MuJoCo|, J";
  difference.x_label = "time, s";
  difference.log_y = true;
  difference.events = spec.events;
  render::Series d;
  d.label = "difference";
  d.color = render::palette(0);
  for (std::size_t k = 0; k < a.x.size(); ++k) {
    d.x.push_back(a.x[k]);
    d.y.push_back(std::max(std::abs(a.y[k] - b.y[k]), 1e-17));
  }
  difference.series = {d};
  plotter.draw(difference, image);
  io::write_png(image, (dir / "zfold_energy_difference.png").string(), 6);
  std::printf("zfold: energies differ by at most %.3g J; plot %s\n", largest, (dir / "zfold_energy.png").c_str());
}

}  // namespace
}  // namespace unfurl
