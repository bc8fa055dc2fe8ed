// Scenes: loaded from a file or a built-in name with --set overrides,
// changed by the same paths, written back as YAML, described.
#include <pybind11/stl.h>

#include "py_types.hpp"
#include "scene_options.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/scene_validation.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl::python {

namespace py = pybind11;

namespace {

std::vector<std::string> names_of(int n, const std::function<std::string(int)>& name) {
  std::vector<std::string> out;
  for (int k = 0; k < n; ++k) out.push_back(name(k));
  return out;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<PyScene>(m, "_Scene")
      .def_property_readonly("name", [](const PyScene& s) { return s.file.scene.name; })
      .def_property_readonly("description", [](const PyScene& s) { return s.file.scene.description; })
      .def_property_readonly("source", [](const PyScene& s) { return s.file.scene.source; })
      .def_property_readonly("bodies",
                             [](const PyScene& s) {
                               const sim::Model& m = s.file.scene.model;
                               return names_of(m.size(), [&](int i) { return m.bodies[i].name; });
                             })
      .def_property_readonly("joints",
                             [](const PyScene& s) {
                               const sim::Model& m = s.file.scene.model;
                               return names_of(m.size(), [&](int i) { return m.joints[i].name; });
                             })
      .def_property_readonly("positions",
                             [](const PyScene& s) {
                               const sim::Model& m = s.file.scene.model;
                               return names_of(m.nq, [&](int c) { return m.position_name(c); });
                             })
      .def_property_readonly("velocities",
                             [](const PyScene& s) {
                               const sim::Model& m = s.file.scene.model;
                               return names_of(m.nv, [&](int c) { return m.velocity_name(c); });
                             })
      .def_property_readonly("latches",
                             [](const PyScene& s) {
                               std::vector<std::string> out;
                               for (const sim::Latch* l : s.file.scene.latches())
                                 out.push_back(s.file.scene.model.joints[l->joint].name);
                               return out;
                             })
      .def_property_readonly("loops",
                             [](const PyScene& s) {
                               std::vector<std::string> out;
                               for (const sim::Loop& l : s.file.scene.loops) out.push_back(l.name);
                               return out;
                             })
      .def_property_readonly("sensors",
                             [](const PyScene& s) {
                               std::vector<std::string> out;
                               for (const sim::Sensor& x : s.file.scene.sensors) out.push_back(x.name);
                               return out;
                             })
      .def_property_readonly("t_end", [](const PyScene& s) { return s.file.scene.run.t_end; })
      .def("_overridden",
           [](const PyScene& s, const std::vector<std::pair<std::string, std::string>>& pairs) {
             return PyScene{sim::apply_overrides(s.file, overrides_from(pairs))};
           })
      .def("_yaml", [](const PyScene& s) { return sim::write_scene_text(s.file); })
      .def("_warnings", [](const PyScene& s) { return sim::scene_warnings(s.file.scene); });
  m.def("_load", [](const std::string& name, const std::vector<std::pair<std::string, std::string>>& pairs) {
    return PyScene{app::read_scene_named(name, overrides_from(pairs))};
  });
  m.def("_builtin_scenes", [] { return sim::builtin_scene_names(); });
  m.def("_generate", [](const std::string& kind, int n, bool compliant, bool flexible, bool snubbers) {
    return PyScene{studies::generate_scene(kind, n, {compliant, flexible, snubbers})};
  });
}

}  // namespace unfurl::python
