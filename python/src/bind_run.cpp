// Runs: a scene simulated with the GIL released (Ctrl+C stops it and raises
// KeyboardInterrupt), its trajectory, loads and sensors as arrays with the
// column names, units and frames of the CLI's files, its events, and its
// summary as summary.json's text.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "py_types.hpp"
#include "scene_clearance.hpp"
#include "unfurl/io/run_columns.hpp"
#include "unfurl/io/run_files.hpp"

namespace unfurl::python {

namespace py = pybind11;

namespace {

// (names, units, frames, data): data[sample][column], as the CSV writes it.
py::tuple table(const std::vector<io::RunColumn>& columns, const sim::Trajectory& tr) {
  std::vector<std::string> names, units, frames;
  for (const io::RunColumn& c : columns) names.push_back(c.name), units.push_back(c.unit), frames.push_back(c.frame);
  py::array_t<double> data({tr.samples.size(), columns.size()});
  auto d = data.mutable_unchecked<2>();
  for (std::size_t k = 0; k < tr.samples.size(); ++k)
    for (std::size_t c = 0; c < columns.size(); ++c) d(k, c) = columns[c].value(tr.samples[k]);
  return py::make_tuple(names, units, frames, data);
}

}  // namespace

void bind_run(py::module_& m) {
  py::class_<PyRun>(m, "_Run")
      .def_property_readonly("status", [](const PyRun& r) { return std::string(sim::run_status_name(r.result.status)); })
      .def_property_readonly("failure",
                             [](const PyRun& r) {
                               return r.result.status == sim::RunStatus::failed ? sim::describe(r.result.failure)
                                                                                : std::string();
                             })
      .def_property_readonly("wall_time", [](const PyRun& r) { return r.result.wall_time_s; })
      .def("_trajectory", [](const PyRun& r) {
        return table(io::trajectory_columns(r.file.scene, r.result.trajectory), r.result.trajectory);
      })
      .def("_loads", [](const PyRun& r) {
        return table(io::load_file_columns(r.file.scene, r.result.trajectory), r.result.trajectory);
      })
      .def("_sensors", [](const PyRun& r) {
        return table(io::sensor_file_columns(r.result.trajectory), r.result.trajectory);
      })
      .def("_events",
           [](const PyRun& r) {
             std::vector<std::pair<double, std::string>> out;
             for (const sim::LatchEvent& e : r.result.trajectory.events)
               out.emplace_back(e.t, r.file.scene.model.joints[e.joint].name);
             return out;
           })
      .def("_summary_json", [](const PyRun& r) { return io::summary_json(r.file.scene, r.result, r.summary); });

  m.def(
      "_simulate",
      [](const PyScene& scene, const std::function<void(double)>& progress) {
        const sim::SceneFile file = scene.file;
        std::atomic<bool> cancel{false};
        std::atomic<double> reached{0};
        sim::RunObserver observer;
        observer.cancel = &cancel;
        observer.on_progress = [&](const sim::StepProgress& p) { reached = p.t; };
        // The summary too: a large array's torque margins and clearance
        // take seconds, and Ctrl+C stops them as it stops the run.
        PyRun run = run_interruptibly(
            [&] {
              PyRun r{file, sim::simulate(file.scene, file.scene.run, observer), {}};
              r.summary = sim::summarize(r.file.scene, r.result, &cancel);
              if (r.result.status != sim::RunStatus::cancelled)
                r.summary.clearance = app::run_clearance(r.file.scene, r.file.visuals, r.result.trajectory, &cancel);
              return r;
            },
            cancel,
            [&] {
              if (progress) progress(reached.load());
            });
        if (progress) progress(run.result.trajectory.empty() ? 0.0 : run.result.trajectory.t_end());
        return run;
      },
      py::arg("scene"), py::arg("progress") = nullptr);
}

}  // namespace unfurl::python
