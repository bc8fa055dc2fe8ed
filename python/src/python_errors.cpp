#include "python_errors.hpp"

#include "cli.hpp"
#include "unfurl/input/input_error.hpp"

namespace unfurl::python {

void register_errors(pybind11::module_& m) {
  // InputError and what derives from it (the builder's SceneInvalid).
  pybind11::register_exception<input::InputError>(m, "SceneError", PyExc_ValueError);
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const app::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace unfurl::python
