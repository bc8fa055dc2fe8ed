// Modes: the natural frequencies, damping ratios and shapes of a scene about
// where its run ends (settled), a run's state at a time, or given positions,
// as `unfurl modes` computes them.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "py_types.hpp"
#include "unfurl/sim/modes.hpp"

namespace unfurl::python {

namespace py = pybind11;

void bind_modes(py::module_& m) {
  m.def(
      "_modes",
      [](const PyScene& scene, std::optional<double> at, std::optional<std::vector<double>> q,
         std::optional<bool> settle) {
        const sim::Scene& s = scene.file.scene;
        sim::LinearizationState state;
        std::string described;
        if (q) {
          if (static_cast<int>(q->size()) != s.model.nq)
            throw py::value_error("q: expected " + std::to_string(s.model.nq) + " positions (scene.positions)");
          state = sim::given_state(s, *q);
          described = "the given positions";
        } else {
          sim::RunSettings run = s.run;
          if (at) run.t_end = std::max(*at, run.sample);
          std::atomic<bool> cancel{false};
          sim::RunObserver observer;
          observer.cancel = &cancel;
          const sim::RunResult result =
              run_interruptibly([&] { return sim::simulate(s, run, observer); }, cancel, [] {});
          if (result.status == sim::RunStatus::failed)
            throw std::runtime_error("the run to the state failed: " + sim::describe(result.failure));
          state = sim::state_of_run(s, result.trajectory, at.value_or(run.t_end));
          described = "the run's state at t = " + std::to_string(state.t) + " s";
        }
        sim::ModesSettings settings;
        settings.settle = settle.value_or(!at && !q);
        if (settings.settle) described += ", settled to its static equilibrium";
        const sim::ModesResult r = sim::linear_modes(s, state.q, state.engaged, settings);
        std::vector<double> f, zeta, fd;
        std::vector<std::string> kinds;
        Eigen::MatrixXd shapes(r.modes.size(), s.model.nv);
        for (std::size_t k = 0; k < r.modes.size(); ++k) {
          f.push_back(r.modes[k].frequency_hz);
          zeta.push_back(r.modes[k].damping_ratio);
          fd.push_back(r.modes[k].damped_frequency_hz);
          kinds.push_back(sim::mode_kind_name(r.modes[k].kind));
          shapes.row(k) = r.modes[k].shape.transpose();
        }
        std::vector<std::string> coordinates;
        for (int c = 0; c < s.model.nv; ++c) coordinates.push_back(s.model.velocity_name(c));
        py::dict out;
        out["frequency_hz"] = f, out["damping_ratio"] = zeta, out["damped_frequency_hz"] = fd;
        out["kind"] = kinds, out["shapes"] = shapes, out["coordinates"] = coordinates, out["q"] = r.q;
        out["state"] = described, out["loop_rank"] = r.loop_rank, out["weak_loop_directions"] = r.weak_loop_directions;
        out["equilibrium_offset"] = r.equilibrium_offset;
        return out;
      },
      py::arg("scene"), py::arg("at") = std::nullopt, py::arg("q") = std::nullopt, py::arg("settle") = std::nullopt);
}

}  // namespace unfurl::python
