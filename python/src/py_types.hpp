// What the module hands to Python: a scene with its visuals, and a finished
// run with the scene it ran (for its tables, pictures and modes).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::python {

struct PyScene {
  sim::SceneFile file;
};

struct PyRun {
  sim::SceneFile file;
  sim::RunResult result;
  sim::RunSummary summary;
};

// (path, value) pairs from Python, as --set overrides.
std::vector<sim::Override> overrides_from(const std::vector<std::pair<std::string, std::string>>& pairs);

// Runs `work` on a thread of its own with the GIL released; every 50 ms
// the calling thread checks for Ctrl+C (then sets `cancel`, waits for the
// work to stop and raises KeyboardInterrupt) and calls `tick` (a progress
// callback) with the GIL held.
template <class Work, class Tick>
auto run_interruptibly(Work work, std::atomic<bool>& cancel, Tick tick);

void bind_scene(pybind11::module_& m);
void bind_builder(pybind11::module_& m);
void bind_run(pybind11::module_& m);
void bind_modes(pybind11::module_& m);
void bind_study(pybind11::module_& m);
void bind_pictures(pybind11::module_& m);

}  // namespace unfurl::python

#include "run_interruptibly.hpp"
