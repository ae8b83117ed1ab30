#pragma once
// The facade's option structs as Python classes (linesurf.ReconstructOptions, ...). Each class
// lists its fields in `_fields` (Python name -> facade field), which linesurf/__init__.py uses to
// map keyword arguments and to refuse unknown ones; enums are their facade names as strings.

#include <pybind11/pybind11.h>

namespace linesurf::python {

void BindOptions(pybind11::module_& module);

}  // namespace linesurf::python
