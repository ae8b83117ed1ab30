#pragma once
// Facade errors as Python exceptions of the linesurf.Error hierarchy (linesurf/_errors.py).

#include "linesurf/linesurf.h"

#include <pybind11/pybind11.h>

namespace linesurf::python {

/// Raises the linesurf.Error subclass of error.code (InvalidInput, InvalidOptions, Cancelled,
/// ...) carrying its code name, stage and message.
[[noreturn]] void RaiseError(const Error& error);

/// Raises linesurf.InvalidInput (stage "python") with `message`.
[[noreturn]] void RaiseInvalidInput(std::string message);

/// The value of `result`, or RaiseError(result.error()).
template <typename T>
T ValueOrRaise(Expected<T>&& result) {
  if (!result) RaiseError(result.error());
  return std::move(result).value();
}

}  // namespace linesurf::python
