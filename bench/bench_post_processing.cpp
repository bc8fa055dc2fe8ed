// What a run costs after the solver, against the number of bodies: the
// clearance check and the torque margins of generated pantographs over
// 2001 samples of their stowed start (its first 2 ms), where every panel
// lies a few millimetres from its neighbours in the stack. Both were
// O(N^2) (every pair of bodies scanned; every element and every sample's
// rates walked once per driven joint) and are now linear in the bodies'
// near neighbours and in the joints: the time per body should stay flat.
// With compliant cross-link pins (bushings, harness elements of every
// driven joint), the torque margins once evaluated every pin by a force
// pass over every body at each driven joint's 101 quasi-static angles,
// O(N^3); each pin's wrenches now go straight to the joints above it.
// The solids are the meshes as drawn (the application's reader), so this
// is built with the renderer.
#include <benchmark/benchmark.h>

#include "scene_clearance.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/torque_margin.hpp"
#include "unfurl/studies/body_solids.hpp"
#include "unfurl/studies/clearance.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl {
namespace {

struct StowedRun {
  sim::SceneFile file;
  sim::RunResult run;
};

StowedRun stowed_run(int stages, studies::CrossPivots pivots = studies::CrossPivots::rigid) {
  StowedRun out{studies::generate_pantograph(stages, pivots), {}};
  sim::RunSettings settings = out.file.scene.run;
  settings.t_end = 2e-3;
  settings.sample = 1e-6;
  settings.rtol = 1e-7;
  settings.atol = 1e-9;
  out.run = sim::simulate(out.file.scene, settings);
  if (out.run.status != sim::RunStatus::finished) throw std::runtime_error("the stowed run failed: " + describe(out.run.failure));
  return out;
}

void BM_ClearanceOfAStowedPantograph(benchmark::State& state) {
  const StowedRun r = stowed_run(static_cast<int>(state.range(0)));
  const studies::BodySolids solids = app::scene_solids(r.file.scene, r.file.visuals, nullptr);
  sim::Clearance c;
  for (auto _ : state) c = studies::check_clearance(r.file.scene, solids, r.run.trajectory);
  state.counters["bodies"] = r.file.scene.model.size();
  state.counters["samples"] = c.samples;
  state.counters["pairs_near"] = static_cast<double>(c.pairs.size());
  state.counters["pairs_beyond"] = static_cast<double>(c.pairs_beyond);
  state.counters["closest_m"] = c.closest() ? c.closest()->distance : -1;
  state.counters["per_body"] =
      benchmark::Counter(r.file.scene.model.size(), benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}
BENCHMARK(BM_ClearanceOfAStowedPantograph)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kSecond)->Iterations(1);

void torque_margins_of(benchmark::State& state, studies::CrossPivots pivots) {
  const StowedRun r = stowed_run(static_cast<int>(state.range(0)), pivots);
  std::vector<sim::JointTorqueMargin> margins;
  for (auto _ : state) margins = sim::torque_margins(r.file.scene, r.run.trajectory);
  state.counters["bodies"] = r.file.scene.model.size();
  state.counters["joints"] = static_cast<double>(margins.size());
  state.counters["per_body"] =
      benchmark::Counter(r.file.scene.model.size(), benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}

void BM_TorqueMarginsOfAStowedPantograph(benchmark::State& state) {
  torque_margins_of(state, studies::CrossPivots::rigid);
}
BENCHMARK(BM_TorqueMarginsOfAStowedPantograph)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kSecond)->Iterations(1);

void BM_TorqueMarginsOfAStowedCompliantPantograph(benchmark::State& state) {
  torque_margins_of(state, studies::CrossPivots::compliant);
}
BENCHMARK(BM_TorqueMarginsOfAStowedCompliantPantograph)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace unfurl
