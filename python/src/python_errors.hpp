// unfurl's errors as Python exceptions: a bad scene or study (with its file,
// line, column and field path) raises unfurl.SceneError, a ValueError; a
// bad argument ValueError; a run or a linearization that fails
// RuntimeError.
#pragma once

#include <pybind11/pybind11.h>

namespace unfurl::python {

void register_errors(pybind11::module_& m);

}  // namespace unfurl::python
