// Error against run time: a scene run by each integrator over a range of
// tolerances (the fixed-step RK4 over a range of steps), every run
// compared with a reference at the same sample times.
//
// The reference is the exact solution where the scene has one (a compound
// pendulum, exact_pendulum.hpp), else the same scene by CVODE BDF at the
// tightest tolerance that still runs. Where a scene with loops latches, the
// joint angles are compared up to the reference's first latch: the deployed
// state can be a branch point where two exact runs part (METHOD.md), so after
// it the final state and the latch times are the measures.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"

namespace unfurl::studies {

struct WorkPrecisionSettings {
  std::vector<sim::IntegratorKind> integrators = sim::all_integrators();
  std::vector<double> tolerances{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};  // rtol; atol = rtol / 100
  std::vector<double> rk4_steps{1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5};
  int repeats = 3;                   // wall time: the median of this many runs...
  double repeat_budget_s = 2.0;      // ...while they take less than this in all
  long max_rk4_steps = 2'000'000;    // RK4 steps smaller than t_end / this are skipped
};

constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

// One integrator at one setting.
struct PrecisionPoint {
  sim::IntegratorKind integrator = sim::IntegratorKind::cvode_bdf;
  double rtol = 0, atol = 0, dt = 0;  // dt: RK4 only
  sim::RunStatus status = sim::RunStatus::finished;
  std::string failure;
  int runs = 0;
  double wall_time_s = 0;  // median
  sim::SolverStats stats;
  long rhs_calls = 0;
  double angle_error = kNotMeasured;  // max |q - q_ref| over joints and samples (up to the first latch)
  double angle_error_whole_run = kNotMeasured;
  double final_error = kNotMeasured;  // max |q(t_end) - q_ref(t_end)|
  double max_loop_gap = kNotMeasured;  // the largest geometric loop gap, m
  double latch_time_error = kNotMeasured;  // max |t - t_ref| over the latches both runs engaged
  int latches_missing = 0;                 // engaged by one run and not the other
};

struct WorkPrecision {
  std::string scene;
  std::string reference;  // what the errors are measured against
  bool exact_reference = false;
  double compared_until = 0;  // the angle errors cover t <= this
  std::vector<PrecisionPoint> points;
};

// Called before each run: what is being run, and how many of all are done.
using ReportProgress = std::function<void(const std::string& what, int done, int total)>;

WorkPrecision measure_work_precision(const sim::Scene& scene, const WorkPrecisionSettings& settings,
                                     const ReportProgress& progress = {});

// For each accuracy 10^-k (k >= 1) reached by some run: the fastest run whose angle
// error is at most that (null where none is).
struct CheapestRun {
  double accuracy = 0;
  const PrecisionPoint* point = nullptr;
};
std::vector<CheapestRun> cheapest_by_accuracy(const WorkPrecision& report);

}  // namespace unfurl::studies
