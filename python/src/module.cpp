// unfurl._unfurl: the solver, studies and pictures for Python. The package
// (python/unfurl/__init__.py) wraps what this returns in Python classes
// with names, units and docstrings.
#include <pybind11/pybind11.h>

#include "py_types.hpp"
#include "python_errors.hpp"

namespace unfurl::python {

std::vector<sim::Override> overrides_from(const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::vector<sim::Override> out;
  for (const auto& [path, value] : pairs) out.push_back({path, value});
  return out;
}

}  // namespace unfurl::python

PYBIND11_MODULE(_unfurl, m) {
  m.doc() = "unfurl's solver, studies and pictures (use the unfurl package)";
  unfurl::python::register_errors(m);
  unfurl::python::bind_scene(m);
  unfurl::python::bind_builder(m);
  unfurl::python::bind_run(m);
  unfurl::python::bind_modes(m);
  unfurl::python::bind_study(m);
  unfurl::python::bind_pictures(m);
}
