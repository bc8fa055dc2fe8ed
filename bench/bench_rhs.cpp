// Cost of one right-hand side (the O(N) sweep plus forces and, with loops,
// the regulator's m extra passes and its gains) for the pantograph and for
// chains of 10 to 1000 bodies. Reported per call and per body.
#include <benchmark/benchmark.h>

#include "dynamics.hpp"
#include "scene_generators.hpp"
#include "scene_yaml.hpp"

namespace unfurl {
namespace {

void run_rhs(benchmark::State& state, const Scene& scene) {
  Dynamics dynamics(scene);
  std::vector<double> y = dynamics.initial_state(), ydot(y.size());
  for (double& x : y) x += 1e-3;  // moving, loops slightly open: the general case
  for (auto _ : state) {
    dynamics.rhs(0, y.data(), ydot.data());
    benchmark::DoNotOptimize(ydot.data());
  }
  state.counters["bodies"] = scene.model.size();
  state.counters["ns_per_body"] =
      benchmark::Counter(static_cast<double>(scene.model.size()), benchmark::Counter::kIsIterationInvariantRate |
                                                                       benchmark::Counter::kInvert);
}

void BM_RhsPantograph(benchmark::State& state) {
  run_rhs(state, load_builtin_scene("pantograph"));
}
BENCHMARK(BM_RhsPantograph)->Unit(benchmark::kMicrosecond);

void BM_RhsPantographPaperGains(benchmark::State& state) {
  run_rhs(state, load_builtin_scene("pantograph", {{"regulator.gains", "paper"}}));
}
BENCHMARK(BM_RhsPantographPaperGains)->Unit(benchmark::kMicrosecond);

void BM_RhsZfold(benchmark::State& state) {
  run_rhs(state, load_builtin_scene("zfold"));
}
BENCHMARK(BM_RhsZfold)->Unit(benchmark::kMicrosecond);

void BM_RhsChain(benchmark::State& state) {
  run_rhs(state, load_scene_text(generate_chain(static_cast<int>(state.range(0))), "chain"));
}
BENCHMARK(BM_RhsChain)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace unfurl
