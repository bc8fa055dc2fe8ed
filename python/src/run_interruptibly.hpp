// run_interruptibly (py_types.hpp): work on its own thread, Ctrl+C and a
// progress callback on the caller's.
#pragma once

#include <atomic>
#include <chrono>
#include <future>

namespace unfurl::python {

template <class Work, class Tick>
auto run_interruptibly(Work work, std::atomic<bool>& cancel, Tick tick) {
  namespace py = pybind11;
  using Result = decltype(work());
  std::future<Result> done;
  {
    py::gil_scoped_release release;
    done = std::async(std::launch::async, std::move(work));
  }
  for (;;) {
    std::future_status status;
    {
      py::gil_scoped_release release;
      status = done.wait_for(std::chrono::milliseconds(50));
    }
    if (PyErr_CheckSignals() != 0) {
      cancel = true;
      {
        py::gil_scoped_release release;
        done.wait();
      }
      throw py::error_already_set();
    }
    if (status == std::future_status::ready) break;
    tick();
  }
  return done.get();
}

}  // namespace unfurl::python
