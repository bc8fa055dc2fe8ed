// The pantograph's whole 20 s deployment per integrator at rtol 1e-8
// (atol 1e-10; RK4 at a fixed 2e-4 s, near its stability limit with the
// regulator at v_max = 2000): wall time, steps, right-hand sides.
#include <benchmark/benchmark.h>

#include "unfurl/sim/simulation.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl {
namespace {

void BM_PantographRun(benchmark::State& state) {
  const auto kind = static_cast<sim::IntegratorKind>(state.range(0));
  const sim::Scene scene = sim::load_builtin_scene("pantograph");
  sim::RunSettings settings = scene.run;
  settings.integrator = kind;
  settings.rtol = 1e-8;
  settings.atol = 1e-10;
  settings.dt = 2e-4;
  sim::RunResult result;
  for (auto _ : state) result = sim::simulate(scene, settings);
  state.SetLabel(std::string(sim::integrator_name(kind)) +
                 (result.status == sim::RunStatus::finished ? "" : " FAILED"));
  state.counters["steps"] = static_cast<double>(result.stats.steps);
  state.counters["rhs_calls"] = static_cast<double>(result.rhs_calls);
  state.counters["jacobians"] = static_cast<double>(result.stats.jacobian_evals);
  state.counters["latched"] = static_cast<double>(result.trajectory.events.size());
  state.counters["closure_m"] = sim::summarize(scene, result).max_closure_gap;
}
BENCHMARK(BM_PantographRun)
    ->DenseRange(0, 4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->ArgName("integrator");

// A run with its loads, peaks and samples recorded on the integrator's
// thread or beside it: the pantograph at its own settings (the workbench's
// re-run), and the z-fold, a tree whose steps are cheap beside the
// hand-over, at the side-by-side's setting (rtol 1e-8).
void run_threads(benchmark::State& state, const sim::Scene& scene, const sim::RunSettings& settings) {
  const auto threads = state.range(0) == 1 ? sim::RunThreads::one : sim::RunThreads::two;
  sim::RunResult result;
  for (auto _ : state) result = sim::simulate(scene, settings, {}, threads);
  state.SetLabel(result.status == sim::RunStatus::finished ? "" : "FAILED");
  state.counters["steps"] = static_cast<double>(result.stats.steps);
}
void BM_PantographRunThreads(benchmark::State& state) {
  const sim::Scene scene = sim::load_builtin_scene("pantograph");
  run_threads(state, scene, scene.run);
}
BENCHMARK(BM_PantographRunThreads)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->ArgName("threads");
void BM_ZfoldRunThreads(benchmark::State& state) {
  const sim::Scene scene = sim::load_builtin_scene("zfold");
  sim::RunSettings settings = scene.run;
  settings.rtol = 1e-8;
  settings.atol = 1e-10;  // rtol / 100, as the side-by-side sets it
  run_threads(state, scene, settings);
}
BENCHMARK(BM_ZfoldRunThreads)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->ArgName("threads");

// The first second of large pantographs by CVODE BDF with GMRES and the
// sweep preconditioner (sparse gains): whole-run cost against size.
void BM_LargePantographFirstSecond(benchmark::State& state) {
  const sim::Scene scene =
      sim::apply_overrides(studies::generate_pantograph(static_cast<int>(state.range(0))), {{"run.t_end", "1"}}).scene;
  sim::RunSettings settings = scene.run;
  settings.rtol = 1e-8;
  settings.atol = 1e-10;
  settings.linear_solver = sim::LinearSolverKind::krylov;
  sim::RunResult result;
  for (auto _ : state) result = sim::simulate(scene, settings);
  state.SetLabel(result.status == sim::RunStatus::finished ? "" : "FAILED");
  state.counters["bodies"] = scene.model.size();
  state.counters["steps"] = static_cast<double>(result.stats.steps);
  state.counters["rhs_calls"] = static_cast<double>(result.rhs_calls);
  state.counters["gmres_iterations"] = static_cast<double>(result.stats.linear_iterations);
}
BENCHMARK(BM_LargePantographFirstSecond)->Arg(10)->Arg(100)->Arg(300)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace unfurl
