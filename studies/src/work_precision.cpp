#include "unfurl/studies/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "unfurl/studies/exact_pendulum.hpp"

namespace unfurl::studies {

namespace {

// Joint angles of the reference at the sample times, and its latch times.
struct Reference {
  std::vector<double> times;
  std::vector<std::vector<double>> q;  // per sample, per coordinate
  std::vector<double> latch_time;      // per latch; NaN if never
  double first_latch = std::numeric_limits<double>::infinity();
};

std::vector<double> latch_times(const sim::Trajectory& trajectory, int latches) {
  std::vector<double> t(latches, kNotMeasured);
  for (const sim::LatchEvent& e : trajectory.events) t[e.latch] = e.t;
  return t;
}

Reference from_trajectory(const sim::Trajectory& trajectory, int latches) {
  Reference r;
  for (const sim::Sample& s : trajectory.samples) {
    r.times.push_back(s.t);
    r.q.emplace_back(s.y.begin(), s.y.begin() + trajectory.layout.nq);
  }
  r.latch_time = latch_times(trajectory, latches);
  // A latch engaged from the start ends no smooth stretch.
  for (double t : r.latch_time)
    if (std::isfinite(t) && t > 0) r.first_latch = std::min(r.first_latch, t);
  return r;
}

Reference from_exact(const ExactPendulum& exact, const sim::RunSettings& run) {
  Reference r;
  for (long k = 0;; ++k) {
    const double t = std::min(k * run.sample, run.t_end);
    r.times.push_back(t);
    r.q.push_back({exact.angle(t)});
    if (t >= run.t_end) break;
  }
  return r;
}

// Compares a run with the reference sample by sample.
void measure_errors(const sim::Scene& scene, const sim::RunResult& run, const Reference& ref, PrecisionPoint& p) {
  const sim::Trajectory& tr = run.trajectory;
  const int nq = scene.model.nq;
  const std::size_t n = std::min(tr.samples.size(), ref.times.size());
  double before = 0, whole = 0, gap = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const sim::Sample& s = tr.samples[k];
    double e = 0;
    for (int c = 0; c < nq; ++c) e = std::max(e, std::abs(s.y[c] - ref.q[k][c]));
    whole = std::max(whole, e);
    if (ref.times[k] <= ref.first_latch) before = std::max(before, e);
    for (const sim::ClosureError& c : s.closure) gap = std::max(gap, c.distance);
  }
  if (run.status != sim::RunStatus::finished || n != ref.times.size()) return;
  p.angle_error = before;
  p.angle_error_whole_run = whole;
  double final_error = 0;
  for (int c = 0; c < nq; ++c) final_error = std::max(final_error, std::abs(tr.samples.back().y[c] - ref.q.back()[c]));
  p.final_error = final_error;
  p.max_loop_gap = scene.loops.empty() ? kNotMeasured : gap;
  if (scene.latches().empty()) return;
  const std::vector<double> t = latch_times(tr, static_cast<int>(scene.latches().size()));
  double worst = 0;
  for (std::size_t l = 0; l < t.size(); ++l) {
    const bool here = std::isfinite(t[l]), there = std::isfinite(ref.latch_time[l]);
    if (here != there) ++p.latches_missing;
    if (here && there) worst = std::max(worst, std::abs(t[l] - ref.latch_time[l]));
  }
  p.latch_time_error = worst;
}

// Runs one setting (repeated for the wall time) and measures it.
PrecisionPoint measure_point(const sim::Scene& scene, sim::RunSettings run, const Reference& ref,
                             const WorkPrecisionSettings& settings) {
  PrecisionPoint p;
  p.integrator = run.integrator;
  p.rtol = run.rtol;
  p.atol = run.atol;
  p.dt = run.integrator == sim::IntegratorKind::rk4 ? run.dt : 0;
  std::vector<double> walls;
  double spent = 0;
  sim::RunResult result;
  while (static_cast<int>(walls.size()) < std::max(1, settings.repeats) &&
         (walls.empty() || spent < settings.repeat_budget_s)) {
    // On one thread: the integrators' own costs compared (the recording's
    // thread beside each would lower all of them by a similar share).
    result = sim::simulate(scene, run, {}, sim::RunThreads::one);
    walls.push_back(result.wall_time_s);
    spent += result.wall_time_s;
    if (result.status != sim::RunStatus::finished) break;
  }
  std::sort(walls.begin(), walls.end());
  p.runs = static_cast<int>(walls.size());
  p.wall_time_s = walls[walls.size() / 2];
  p.status = result.status;
  if (result.status == sim::RunStatus::failed) p.failure = sim::describe(result.failure);
  p.stats = result.stats;
  p.rhs_calls = result.rhs_calls;
  measure_errors(scene, result, ref, p);
  return p;
}

// CVODE BDF at the tightest tolerance that runs to the end.
std::optional<sim::RunResult> tight_reference(const sim::Scene& scene, std::string& description) {
  for (double rtol : {1e-13, 1e-12, 1e-11, 1e-10}) {
    sim::RunSettings run = scene.run;
    run.integrator = sim::IntegratorKind::cvode_bdf;
    run.rtol = rtol;
    run.atol = rtol / 100;
    // A reference holds its tolerance, whatever the steps: raised to the
    // round-off it would be no tighter than the runs it measures.
    run.roundoff_guard = false;
    sim::RunResult result = sim::simulate(scene, run);
    if (result.status != sim::RunStatus::finished) continue;
    std::ostringstream s;
    s << "cvode-bdf at rtol " << rtol << ", atol " << run.atol
      << " (the tightest tolerance of 1e-13, 1e-12, ... that runs to the end; " << result.stats.steps << " steps, "
      << result.wall_time_s << " s)";
    description = s.str();
    return result;
  }
  return std::nullopt;
}

}  // namespace

WorkPrecision measure_work_precision(const sim::Scene& scene, const WorkPrecisionSettings& settings,
                                     const ReportProgress& progress) {
  WorkPrecision report;
  report.scene = scene.name;
  const int latches = static_cast<int>(scene.latches().size());
  std::vector<sim::RunSettings> runs;
  for (sim::IntegratorKind kind : settings.integrators) {
    sim::RunSettings run = scene.run;
    run.integrator = kind;
    if (kind == sim::IntegratorKind::rk4) {
      for (double dt : settings.rk4_steps) {
        if (run.t_end / dt > static_cast<double>(settings.max_rk4_steps)) continue;
        run.dt = dt;
        runs.push_back(run);
      }
      continue;
    }
    for (double rtol : settings.tolerances) {
      run.rtol = rtol;
      run.atol = rtol / 100;
      runs.push_back(run);
    }
  }
  const int total = static_cast<int>(runs.size()) + 1;

  Reference ref;
  if (const auto exact = exact_pendulum(scene)) {
    ref = from_exact(*exact, scene.run);
    report.exact_reference = true;
    std::ostringstream s;
    s << "the exact solution (compound pendulum: omega = " << exact->omega << " rad/s, released "
      << exact->phi0 << " rad from its equilibrium; Jacobi sn)";
    report.reference = s.str();
  } else {
    if (progress) progress("reference", 0, total);
    const auto tight = tight_reference(scene, report.reference);
    if (!tight) throw std::runtime_error(scene.name + ": no reference: CVODE BDF fails at every tolerance down to 1e-10");
    ref = from_trajectory(tight->trajectory, latches);
  }
  // Loops that latch meet a branch point at the deployed state; a tree has
  // none and is compared over the whole run.
  if (scene.loops.empty()) ref.first_latch = std::numeric_limits<double>::infinity();
  report.compared_until = std::min(ref.first_latch, scene.run.t_end);

  int done = 1;
  for (const sim::RunSettings& run : runs) {
    if (progress) {
      std::ostringstream what;
      what << sim::integrator_name(run.integrator) << " ";
      if (run.integrator == sim::IntegratorKind::rk4)
        what << "dt " << run.dt;
      else
        what << "rtol " << run.rtol;
      progress(what.str(), done, total);
    }
    report.points.push_back(measure_point(scene, run, ref, settings));
    ++done;
  }
  if (progress) progress("done", total, total);
  return report;
}

std::vector<CheapestRun> cheapest_by_accuracy(const WorkPrecision& report) {
  // Errors below 1e-16 rad are round-off: they count as 1e-16.
  double best = std::numeric_limits<double>::infinity(), worst = 0;
  for (const PrecisionPoint& p : report.points)
    if (std::isfinite(p.angle_error)) {
      best = std::min(best, std::max(p.angle_error, 1e-16));
      worst = std::max(worst, std::max(p.angle_error, 1e-16));
    }
  std::vector<CheapestRun> out;
  if (!std::isfinite(best)) return out;
  // Accuracies from 0.1 (or the worst run, if better) down to the best run.
  for (int k = std::min(-1, static_cast<int>(std::ceil(std::log10(worst)))); std::pow(10.0, k) >= best; --k) {
    CheapestRun c;
    c.accuracy = std::pow(10.0, k);
    for (const PrecisionPoint& p : report.points)
      if (std::isfinite(p.angle_error) && p.angle_error <= c.accuracy &&
          (!c.point || p.wall_time_s < c.point->wall_time_s))
        c.point = &p;
    out.push_back(c);
  }
  return out;
}

}  // namespace unfurl::studies
