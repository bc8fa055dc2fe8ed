#include "unfurl/studies/scaling.hpp"

#include <algorithm>
#include <chrono>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/studies/rhs_timing.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::studies {

std::string family_label(const ScalingScene& s) {
  return s.family + (s.variant.empty() ? "" : " (" + s.variant + ")");
}

sim::Scene load_scaling_scene(const ScalingScene& s) {
  std::vector<sim::Override> overrides;
  for (const auto& [path, value] : s.overrides) overrides.push_back({path, value});
  const sim::SceneFile file = s.family == "chain"   ? generate_chain(s.size)
                              : s.family == "zfold" ? generate_zfold(s.size)
                                                    : generate_pantograph(s.size);
  return sim::apply_overrides(file, overrides).scene;
}

RhsTiming time_right_hand_side(const ScalingScene& s, double seconds) {
  using Clock = std::chrono::steady_clock;
  const sim::Scene scene = load_scaling_scene(s);
  sim::Dynamics dynamics(scene);
  const RhsTimingStates y = rhs_timing_states(dynamics);
  std::vector<double> ydot(y.a.size());
  RhsTiming t;
  t.scene = s;
  t.bodies = scene.model.size();
  t.loop_components = dynamics.layout().m;
  t.states = dynamics.size();
  // Batches of calls lasting about seconds / 5 each; the median batch.
  long calls = 1;
  for (;;) {
    const auto start = Clock::now();
    for (long k = 0; k < calls; ++k) dynamics.rhs(0, y[k].data(), ydot.data());
    if (std::chrono::duration<double>(Clock::now() - start).count() > seconds / 20) break;
    calls *= 2;
  }
  calls = std::max(1L, calls * 4);
  std::vector<double> per_call;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = Clock::now();
    for (long k = 0; k < calls; ++k) dynamics.rhs(0, y[k].data(), ydot.data());
    per_call.push_back(std::chrono::duration<double>(Clock::now() - start).count() / calls);
  }
  std::sort(per_call.begin(), per_call.end());
  t.seconds_per_call = per_call[2];
  t.ns_per_body = 1e9 * t.seconds_per_call / t.bodies;
  return t;
}

RunTiming time_whole_run(const ScalingScene& s, sim::IntegratorKind integrator, sim::LinearSolverKind linear_solver,
                         double t_end, double budget_s) {
  const sim::Scene scene = load_scaling_scene(s);
  sim::RunSettings run = scene.run;
  run.integrator = integrator;
  run.linear_solver = linear_solver;
  run.t_end = t_end;
  run.sample = t_end / 10;
  run.rtol = 1e-8;
  run.atol = 1e-10;
  run.max_wall_time = budget_s;
  const sim::RunResult result = sim::simulate(scene, run);
  RunTiming t;
  t.scene = s;
  t.method = sim::integrator_name(integrator);
  if (integrator == sim::IntegratorKind::cvode_bdf || integrator == sim::IntegratorKind::arkode_dirk)
    t.method += linear_solver == sim::LinearSolverKind::krylov ? ", GMRES + sweep preconditioner" : ", dense Newton";
  t.bodies = scene.model.size();
  t.states = result.trajectory.layout.size();
  t.status = result.status;
  if (result.status == sim::RunStatus::failed) t.failure = sim::describe(result.failure);
  t.t_reached = result.trajectory.empty() ? 0 : result.trajectory.t_end();
  t.wall_time_s = result.wall_time_s;
  t.steps = result.stats.steps;
  t.rhs_calls = result.rhs_calls;
  t.jacobians = result.stats.jacobian_evals;
  t.linear_iterations = result.stats.linear_iterations;
  t.max_closure_gap = sim::summarize(scene, result).max_closure_gap;
  return t;
}

}  // namespace unfurl::studies
