#include "tools/python/bind_options.h"

#include "linesurf/linesurf.h"

#include "tools/python/errors.h"

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <pybind11/stl.h>

namespace linesurf::python {
namespace {

namespace py = pybind11;

/// The field of `options` at `path` (one of its schema's), typed Field.
template <typename Field, typename Options>
Field& FieldAt(Options& options, std::string_view path) {
  Field* found = nullptr;
  VisitOptions(options, [&](const OptionSpec& spec, auto& field) {
    if constexpr (std::is_same_v<std::remove_reference_t<decltype(field)>, Field>) {
      if (spec.path == path) found = &field;
    }
  });
  return *found;  // the path comes from the same schema: always found
}

/// A Python class of an options struct whose attributes are the schema's options under `prefix`
/// ("detection." for DetectionParameters, "" for ReconstructOptions) and the nested groups added
/// with Group; `_fields` lists them in order, for linesurf/__init__.py's keyword arguments.
template <typename T>
class OptionsClass {
 public:
  OptionsClass(py::module_& module, const char* name, const char* doc, std::string prefix)
      : class_(module, name, doc) {
    class_.def(py::init<>());
    T defaults;
    VisitOptions(defaults, [&](const OptionSpec& spec, auto& field) {
      if (spec.path.substr(0, prefix.size()) != prefix) return;
      const std::string name(spec.path.substr(prefix.size()));
      if (name.find('.') != std::string::npos) return;  // a nested group's: bound there
      this->template Bind<std::remove_reference_t<decltype(field)>>(
          name, std::string(spec.path), spec);
    });
  }

  /// A nested options struct (`detection`, `weights`, ...), itself an OptionsClass.
  template <typename G>
  OptionsClass& Group(const char* name, G T::*member, const char* doc) {
    class_.def_readwrite(name, member, doc);
    fields_.push_back(name);
    return *this;
  }

  py::class_<T> Finish() {
    class_.attr("_fields") = py::tuple(py::cast(fields_));
    return class_;
  }

 private:
  template <typename Field>
  void Bind(const std::string& name, const std::string& path, const OptionSpec& spec) {
    std::string doc(spec.help);
    if (const std::string range = OptionRangeText(spec.range);
        !range.empty() && !std::is_enum_v<Field> && !std::is_same_v<Field, bool>) {
      doc += " " + range;
    }
    if constexpr (std::is_enum_v<Field>) {
      // An enum is its facade name ("exterior", "clp", ...).
      class_.def_property(
          name.c_str(),
          [path](T& o) { return std::string(OptionEnum<Field>::Name(FieldAt<Field>(o, path))); },
          [path, name](T& o, const std::string& value) {
            const std::optional<Field> parsed = OptionEnumFromName<Field>(value);
            if (!parsed) throw py::value_error(name + ": unknown value '" + value + "'");
            FieldAt<Field>(o, path) = *parsed;
          },
          doc.c_str());
    } else {
      class_.def_property(
          name.c_str(),
          [path](T& o) { return FieldAt<Field>(o, path); },
          [path](T& o, const Field& value) { FieldAt<Field>(o, path) = value; },
          doc.c_str());
    }
    fields_.push_back(name);
  }

  py::class_<T> class_;
  std::vector<std::string> fields_;
};

// validate(): raises linesurf.InvalidOptions naming the first offending field.
template <typename T>
void AddValidate(py::class_<T>& c) {
  c.def(
      "validate",
      [](const T& o) {
        if (const Status status = o.Validate(); !status) RaiseError(status.error());
      },
      "Raises linesurf.InvalidOptions naming the first field out of its documented range.");
}

}  // namespace

void BindOptions(py::module_& m) {
  OptionsClass<DetectionParameters>(m,
                                    "DetectionParameters",
                                    "RANSAC plane detection (docs/design/plane_detection.md).",
                                    "detection.")
      .Finish();
  OptionsClass<EnergyWeights>(m,
                              "EnergyWeights",
                              "Weights of the energy terms (docs/design/reconstruction.md).",
                              "weights.")
      .Finish();
  OptionsClass<SolverOptions>(
      m, "SolverOptions", "LP labelling (docs/design/solver.md).", "solver.")
      .Finish();
  OptionsClass<QualityOptions>(
      m, "QualityOptions", "Figures without ground truth (docs/user/evaluation.md).", "quality.")
      .Finish();

  using R = ReconstructOptions;
  py::class_<R> reconstruct =
      OptionsClass<R>(m, "ReconstructOptions", "Options of reconstruct().", "")
          .Group("detection", &R::detection, "DetectionParameters")
          .Group("weights", &R::weights, "EnergyWeights")
          .Group("solver", &R::solver, "SolverOptions")
          .Group("quality", &R::quality, "QualityOptions")
          .Finish();
  AddValidate(reconstruct);

  using O = DetectOptions;
  py::class_<O> detect = OptionsClass<O>(m, "DetectOptions", "Options of detect_planes().", "")
                             .Group("detection", &O::detection, "DetectionParameters")
                             .Finish();
  AddValidate(detect);

  // Every option of the schema, for the tests that compare the front ends' names with it.
  m.def("_option_paths", [] {
    std::vector<std::string> paths;
    ReconstructOptions defaults;
    VisitOptions(defaults, [&](const OptionSpec& spec, auto&) { paths.emplace_back(spec.path); });
    return paths;
  });
}

}  // namespace linesurf::python
