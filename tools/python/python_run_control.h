#pragma once
// Runs a facade call with the GIL released and Python callbacks behind a RunControl.
//
// The call runs on a helper thread while the calling (main) thread waits with the GIL released
// and checks for signals every kSignalPollInterval: CPython runs signal handlers only on the
// main thread, so PyErr_CheckSignals from the engine's worker threads would never see a
// Ctrl-C. A KeyboardInterrupt (or any exception a handler raises) sets the cancel flag and is
// re-raised once the call has returned kCancelled. Progress and log callbacks take the GIL; an
// exception they raise cancels the run and is re-raised in its place.

#include "linesurf/linesurf.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <optional>

#include <pybind11/pybind11.h>

namespace linesurf::python {

namespace py = pybind11;

inline constexpr std::chrono::milliseconds kSignalPollInterval{20};

/// The Python side of one run: callbacks, the cancel flag and the first Python exception.
class PythonRunControl {
 public:
  /// `progress(stage: str, fraction: float)` returning True cancels; `log(level: str, stage:
  /// str, message: str)`; either may be None.
  PythonRunControl(py::object progress, py::object log);
  ~PythonRunControl();

  /// Runs `call(control)` as described above and returns its result; raises the pending Python
  /// exception if there is one. Call with the GIL held.
  template <typename T>
  Expected<T> Run(const std::function<Expected<T>(const RunControl&)>& call) {
    std::optional<Expected<T>> result;
    RunReleased([&](const RunControl& control) { result.emplace(call(control)); });
    RaisePending();
    return std::move(*result);
  }

 private:
  class Sink;

  void RunReleased(const std::function<void(const RunControl&)>& call);
  // With the GIL held: keeps `error` (the first one wins) and cancels.
  void KeepErrorAndCancel(py::error_already_set&& error);
  void RaisePending();

  py::object progress_;
  py::object log_;
  std::atomic<bool> cancel_{false};
  std::optional<py::error_already_set> pending_;  // guarded by the GIL
};

}  // namespace linesurf::python
