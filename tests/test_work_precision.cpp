// The work-precision report: errors against the pendulum's exact solution,
// the exact solution itself, the cheapest-integrator table, and the files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "unfurl/studies/exact_pendulum.hpp"
#include "support.hpp"
#include "unfurl/studies/work_precision.hpp"

namespace unfurl {
namespace {

namespace fs = std::filesystem;

TEST(ExactPendulum, JacobiSnMeetsItsIdentities) {
  for (double u : {0.0, 0.3, 1.7, -2.2}) EXPECT_NEAR(studies::jacobi_sn(u, 0), std::sin(u), 1e-15);
  for (double m : {0.1, 0.5, 0.9, 0.99}) {
    const double K = std::comp_ellint_1(std::sqrt(m));
    EXPECT_NEAR(studies::jacobi_sn(K, m), 1.0, 1e-14) << m;
    EXPECT_NEAR(studies::jacobi_sn(K / 2, m), 1 / std::sqrt(1 + std::sqrt(1 - m)), 1e-14) << m;
    EXPECT_NEAR(studies::jacobi_sn(-0.4, m), -studies::jacobi_sn(0.4, m), 1e-15);
  }
}

TEST(ExactPendulum, AgreesWithATightRun) {
  const sim::Scene scene = test::scene_file("pendulum");
  const auto exact = studies::exact_pendulum(scene);
  ASSERT_TRUE(exact);
  EXPECT_NEAR(exact->angle(0), scene.q0[0], 1e-14);
  sim::RunSettings run = scene.run;
  run.integrator = sim::IntegratorKind::arkode_erk;
  run.rtol = 1e-12;
  run.atol = 1e-14;
  const sim::RunResult result = sim::simulate(scene, run);
  double worst = 0;
  for (const sim::Sample& s : result.trajectory.samples) worst = std::max(worst, std::abs(s.y[0] - exact->angle(s.t)));
  EXPECT_LT(worst, 1e-9);
}

TEST(ExactPendulum, ReleasedOneTurnOnIsTheSameMotionOneTurnOn) {
  const sim::Scene scene = test::scene_file("pendulum");
  const auto plain = studies::exact_pendulum(scene);
  char q0[32];
  std::snprintf(q0, sizeof q0, "%.17g", 2.5 + 2 * M_PI);
  const auto turned = studies::exact_pendulum(test::scene_file("pendulum", {{"initial.q.hinge", q0}}));
  ASSERT_TRUE(plain && turned);
  for (double t : {0.0, 0.7, 3.1, 9.9}) EXPECT_NEAR(turned->angle(t), plain->angle(t) + 2 * M_PI, 1e-9) << t;
}

TEST(ExactPendulum, OnlyForAPendulum) {
  EXPECT_FALSE(studies::exact_pendulum(test::scene_file("double_pendulum")));
  EXPECT_FALSE(studies::exact_pendulum(test::scene_file("zfold")));
  EXPECT_FALSE(studies::exact_pendulum(test::scene_file("pendulum", {{"initial.dq.hinge", "0.5"}})));
}

// Its first half swing (t < 1 s of a 2.9 s period). Over many swings an
// undamped oscillator's global error grows with the step count, as CVODE
// bounds the error per step: the 10 s scene reaches 1e3-1e4 times rtol
// with BDF (docs/work-precision/pendulum).
studies::WorkPrecision pendulum_report() {
  studies::WorkPrecisionSettings settings;
  settings.tolerances = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  settings.rk4_steps = {2e-2, 1e-2, 5e-3, 2.5e-3};
  settings.repeats = 1;
  return studies::measure_work_precision(test::scene_file("pendulum", {{"run.t_end", "1"}}), settings);
}

TEST(WorkPrecision, PendulumErrorsAreWithinAHundredTimesTheTolerance) {
  const studies::WorkPrecision report = pendulum_report();
  EXPECT_TRUE(report.exact_reference);
  for (const studies::PrecisionPoint& p : report.points) {
    ASSERT_EQ(p.status, sim::RunStatus::finished) << sim::integrator_name(p.integrator);
    if (p.integrator == sim::IntegratorKind::rk4) continue;
    EXPECT_LT(p.angle_error, 100 * p.rtol) << sim::integrator_name(p.integrator) << " at rtol " << p.rtol;
    EXPECT_GT(p.angle_error, 0);
  }
}

TEST(WorkPrecision, PendulumErrorFallsAsTheToleranceTightens) {
  const studies::WorkPrecision report = pendulum_report();
  for (sim::IntegratorKind kind : sim::all_integrators()) {
    std::vector<double> errors;
    for (const studies::PrecisionPoint& p : report.points)
      if (p.integrator == kind) errors.push_back(p.angle_error);
    ASSERT_GE(errors.size(), 4u);
    // Never more than a little up from one setting to the next, and down by
    // orders of magnitude over the range.
    for (std::size_t k = 1; k < errors.size(); ++k)
      EXPECT_LT(errors[k], 3 * errors[k - 1]) << sim::integrator_name(kind) << " setting " << k;
    if (kind == sim::IntegratorKind::rk4) {
      // Fourth order: halving the step divides the error by about 16.
      for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_GT(errors[k - 1] / errors[k], 10) << k;
    } else {
      EXPECT_LT(errors.back(), 1e-4 * errors.front()) << sim::integrator_name(kind);
    }
  }
}

TEST(WorkPrecision, CheapestRunMeetsEachAccuracyAtTheLeastWallTime) {
  studies::WorkPrecision report;
  auto point = [](sim::IntegratorKind kind, double wall, double error) {
    studies::PrecisionPoint p;
    p.integrator = kind;
    p.wall_time_s = wall;
    p.angle_error = error;
    return p;
  };
  report.points = {point(sim::IntegratorKind::cvode_bdf, 1.0, 3e-3), point(sim::IntegratorKind::cvode_bdf, 2.0, 4e-6),
                   point(sim::IntegratorKind::arkode_erk, 0.5, 2e-2), point(sim::IntegratorKind::arkode_erk, 3.0, 5e-7),
                   point(sim::IntegratorKind::rk4, 1.5, studies::kNotMeasured)};
  const auto cheapest = studies::cheapest_by_accuracy(report);
  ASSERT_EQ(cheapest.size(), 6u);  // 1e-1 .. 1e-6
  EXPECT_EQ(cheapest[0].point, &report.points[2]);  // 1e-1: erk at 0.5 s
  EXPECT_EQ(cheapest[1].point, &report.points[0]);  // 1e-2: bdf at 1 s
  EXPECT_EQ(cheapest[2].point, &report.points[1]);  // 1e-3: bdf at 2 s
  EXPECT_EQ(cheapest[3].point, &report.points[1]);  // 1e-4
  EXPECT_EQ(cheapest[4].point, &report.points[1]);  // 1e-5
  EXPECT_EQ(cheapest[5].point, &report.points[3]);  // 1e-6: erk at 3 s
}

TEST(WorkPrecision, ExactRunsCountAsRoundOff) {
  studies::WorkPrecision report;
  studies::PrecisionPoint exact;
  exact.angle_error = 0;
  exact.wall_time_s = 1;
  report.points = {exact};
  // One row: the worst run already reaches round-off.
  const auto cheapest = studies::cheapest_by_accuracy(report);
  ASSERT_EQ(cheapest.size(), 1u);
  EXPECT_DOUBLE_EQ(cheapest[0].accuracy, 1e-16);
  EXPECT_EQ(cheapest[0].point, &report.points[0]);
}

TEST(WorkPrecision, ReportCommandWritesTheTableThePlotAndTheSummary) {
  const fs::path dir = fs::temp_directory_path() / ("unfurl_report_" + std::to_string(::getpid()));
  const std::string command = std::string(UNFURL_BINARY) + " report zfold --t-end 6 --integrators cvode-bdf,rk4" +
                              " --tolerances 1e-5,1e-7 --steps 1e-3 --repeats 1 --quiet --out " + dir.string();
  ASSERT_EQ(WEXITSTATUS(std::system(command.c_str())), 0);
  std::ifstream csv(dir / "work_precision.csv");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 1 + 3);
  for (const char* f : {"WORK_PRECISION.md", "work_precision.png", "work_precision_latch.png", "work_precision_final.png"})
    EXPECT_GT(fs::file_size(dir / f), 1000u) << f;
  std::ifstream md(dir / "WORK_PRECISION.md");
  const std::string text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(text.find("Cheapest integrator for each accuracy"), std::string::npos);
  EXPECT_NE(text.find("cvode-bdf at rtol 1e-13"), std::string::npos) << "the reference is named";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace unfurl
