#include "tools/python/errors.h"

#include <utility>

namespace linesurf::python {

namespace py = pybind11;

void RaiseError(const Error& error) {
  // from_code picks the class; the instance carries code, stage and message as attributes.
  py::object from_code = py::module_::import("linesurf._errors").attr("from_code");
  py::object exception = from_code(ErrorCodeName(error.code), error.stage, error.message);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(exception.ptr())), exception.ptr());
  throw py::error_already_set();
}

void RaiseInvalidInput(std::string message) {
  RaiseError(Error{ErrorCode::kInvalidInput, "python", std::move(message)});
}

}  // namespace linesurf::python
