// Cost of one right-hand side (the O(N) sweep plus forces and, with loops,
// the regulator's gains from the current W) for the pantograph, and for
// chains, z-folds and pantographs of about 10 to 10,000 bodies. Reported
// per call and per body: flat per body is O(N).
#include <benchmark/benchmark.h>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/studies/rhs_timing.hpp"
#include "unfurl/studies/scene_generators.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace unfurl {
namespace {

void run_rhs(benchmark::State& state, const sim::Scene& scene) {
  sim::Dynamics dynamics(scene);
  const studies::RhsTimingStates y = studies::rhs_timing_states(dynamics);
  std::vector<double> ydot(y.a.size());
  long call = 0;
  for (auto _ : state) {
    dynamics.rhs(0, y[call++].data(), ydot.data());
    benchmark::DoNotOptimize(ydot.data());
  }
  state.counters["bodies"] = scene.model.size();
  state.counters["ns_per_body"] =
      benchmark::Counter(static_cast<double>(scene.model.size()), benchmark::Counter::kIsIterationInvariantRate |
                                                                       benchmark::Counter::kInvert);
}

void BM_RhsPantograph(benchmark::State& state) { run_rhs(state, sim::load_builtin_scene("pantograph")); }
BENCHMARK(BM_RhsPantograph)->Unit(benchmark::kMicrosecond);

void BM_RhsPantographPaperGains(benchmark::State& state) {
  run_rhs(state, sim::load_builtin_scene("pantograph", {{"regulator.gains", "paper"}}));
}
BENCHMARK(BM_RhsPantographPaperGains)->Unit(benchmark::kMicrosecond);

void BM_RhsZfold(benchmark::State& state) { run_rhs(state, sim::load_builtin_scene("zfold")); }
BENCHMARK(BM_RhsZfold)->Unit(benchmark::kMicrosecond);

void BM_RhsChain(benchmark::State& state) {
  run_rhs(state, studies::generate_chain(static_cast<int>(state.range(0))).scene);
}
BENCHMARK(BM_RhsChain)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_RhsZfoldPanels(benchmark::State& state) {
  run_rhs(state, studies::generate_zfold(static_cast<int>(state.range(0))).scene);
}
BENCHMARK(BM_RhsZfoldPanels)->Arg(9)->Arg(99)->Arg(999)->Arg(9999)->Unit(benchmark::kMicrosecond);

// Stages 3 .. 3333: 11 .. 10,001 bodies, 9 .. 9999 loop components (dense
// gains up to 48 components, sparse beyond).
void BM_RhsPantographStages(benchmark::State& state) {
  run_rhs(state, studies::generate_pantograph(static_cast<int>(state.range(0))).scene);
}
BENCHMARK(BM_RhsPantographStages)->Arg(3)->Arg(10)->Arg(33)->Arg(333)->Arg(3333)->Unit(benchmark::kMicrosecond);

// N flexible beams hinged end to end (each 1 m, two fixed-interface modes
// and, but for the last, its tip's six constraint modes: 8 elastic
// coordinates a beam): the extended (6 + m) sweep's cost per body.
sim::Scene flexible_chain(int beams) {
  sim::flexible::BeamSection section;
  section.length = 1, section.axial_stiffness = 1e7, section.bending_stiffness_y = section.bending_stiffness_z = 500;
  section.torsional_stiffness = 300, section.mass_per_length = 1.5, section.polar_inertia_per_length = 1e-3;
  section.elements = 4;
  const auto inner = std::make_shared<const sim::flexible::FlexibleBody>(
      sim::flexible::beam_body(section, 2, 0.005, {sim::Vec3(1, 0, 0)}));
  const auto last = std::make_shared<const sim::flexible::FlexibleBody>(sim::flexible::beam_body(section, 2, 0.005, {}));
  sim::SceneBuilder b("flexible chain");
  b.fixed_base("ground");
  for (int k = 0; k < beams; ++k) {
    sim::Body beam;
    beam.name = "beam" + std::to_string(k);
    beam.flexible = k + 1 < beams ? inner : last;
    b.body(beam, k == 0 ? "ground" : "beam" + std::to_string(k - 1),
           sim::joints::revolute("hinge" + std::to_string(k), sim::Vec3::UnitZ(), k == 0 ? sim::Vec3::Zero() : sim::Vec3(1, 0, 0),
                                 sim::Vec3::Zero()));
  }
  return b.build().scene;
}

// N flexible plates hinged edge to edge (0.9 x 1.2 m panels, 4 x 6
// elements, four fixed-interface modes and, but for the last, the three
// constraint modes of its tied outboard hinge line: 7 elastic coordinates
// a plate).
sim::Scene flexible_plate_chain(int plates) {
  sim::flexible::PlateBodySpec spec;
  spec.plate.length_x = 0.9, spec.plate.length_y = 1.2, spec.plate.bending_stiffness = 7435, spec.plate.poisson = 0.33;
  spec.plate.mass_per_area = 3.7, spec.plate.elements_x = 4, spec.plate.elements_y = 6;
  spec.corner = sim::Vec3(-0.45, 0, 0);
  const auto last = std::make_shared<const sim::flexible::FlexibleBody>(sim::flexible::plate_body(spec));
  spec.hinge_lines = {sim::flexible::PlateEdge::y1};
  spec.attachments = {sim::Vec3(0, 1.2, 0)};
  const auto inner = std::make_shared<const sim::flexible::FlexibleBody>(sim::flexible::plate_body(spec));
  sim::SceneBuilder b("flexible plate chain");
  b.fixed_base("ground");
  for (int k = 0; k < plates; ++k) {
    sim::Body plate;
    plate.name = "plate" + std::to_string(k);
    plate.flexible = k + 1 < plates ? inner : last;
    b.body(plate, k == 0 ? "ground" : "plate" + std::to_string(k - 1),
           sim::joints::revolute("hinge" + std::to_string(k), sim::Vec3::UnitX(),
                                 k == 0 ? sim::Vec3::Zero() : sim::Vec3(0, 1.2, 0), sim::Vec3::Zero()));
  }
  return b.build().scene;
}

void BM_RhsFlexiblePlateChain(benchmark::State& state) {
  run_rhs(state, flexible_plate_chain(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_RhsFlexiblePlateChain)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kMicrosecond);

void BM_RhsFlexibleChain(benchmark::State& state) { run_rhs(state, flexible_chain(static_cast<int>(state.range(0)))); }
BENCHMARK(BM_RhsFlexibleChain)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace unfurl
