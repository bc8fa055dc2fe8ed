#include "unfurl/studies/stability_results.hpp"

#include <cmath>
#include <sstream>

#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/stability_verdicts.hpp"

namespace unfurl::studies {

StabilityResult run_stability_case(const StabilityCase& c) {
  StabilityResult r;
  r.spec = c;
  const sim::Scene scene = stability_scene(c);
  sim::RunResult run = sim::simulate(scene, scene.run);
  const sim::RunSummary s = sim::summarize(scene, run);
  r.status = run.status;
  if (run.status == sim::RunStatus::failed) {
    r.failed_check = run.failure.check;
    r.failure = sim::describe(run.failure);
  }
  r.t_reached = s.t_reached;
  r.wall_time_s = run.wall_time_s;
  r.min_step = run.stats.min_step;
  r.steps = run.stats.steps;
  r.rhs_calls = run.rhs_calls;
  r.bodies = scene.model.size();
  r.loop_components = run.trajectory.layout.m;
  r.energy_initial = s.energy_initial;
  r.energy_final = s.energy_final;
  r.max_closure_gap = s.max_closure_gap;
  r.max_closure_angle = s.max_closure_angle;
  r.latches_engaged = static_cast<int>(s.latch_times.size());
  r.latches_total = static_cast<int>(scene.latches().size());
  if (c.conservative) {
    double drift = 0;
    for (const sim::Sample& x : run.trajectory.samples)
      drift = std::max(drift, std::abs(x.energy.total() - s.energy_initial));
    r.energy_drift = drift / std::abs(s.energy_initial);
  }
  if (c.branches) r.notes = describe_branches(scene, run.trajectory);
  r.energy_rose = !c.conservative && s.energy_final - s.energy_initial > 0.01 * std::abs(s.energy_initial) + 1e-9;
  if (r.energy_rose) {
    std::ostringstream note;
    note << "energy rose from " << s.energy_initial << " to " << s.energy_final
         << " J: a passive mechanism cannot gain energy, so this run is not physical";
    r.notes.push_back(note.str());
  }
  if (c.closing_time && !run.trajectory.empty()) {
    std::ostringstream note;
    note << "started open by a gap of " << largest_gap(run.trajectory.samples.front())
         << "; below 1e-3 of that at t = " << closing_time(run.trajectory, 1e-3 * largest_gap(run.trajectory.samples.front()))
         << " s, below 1e-9 at t = " << closing_time(run.trajectory, 1e-9) << " s (designed slowest pole: b0 = p0 v_max = "
         << scene.regulator.p0 * scene.regulator.v_max.value_or(0) << " 1/s)";
    r.notes.push_back(note.str());
  }
  if (c.conservative) r.trajectory = std::move(run.trajectory);
  return r;
}

}  // namespace unfurl::studies
