#include "tools/python/bind_options.h"

#include "linesurf/linesurf.h"

#include "tools/python/errors.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/stl.h>

namespace linesurf::python {
namespace {

namespace py = pybind11;

// A py::class_ that records the names of the fields it exposes, in declaration order.
template <typename T>
class OptionsClass {
 public:
  OptionsClass(py::module_& module, const char* name, const char* doc) : class_(module, name, doc) {
    class_.def(py::init<>());
  }

  template <typename Value>
  OptionsClass& Field(const char* name, Value T::*member, const char* doc) {
    class_.def_readwrite(name, member, doc);
    fields_.push_back(name);
    return *this;
  }

  // An enum field exposed as its facade name ("exterior", "clp", ...).
  template <typename Enum>
  OptionsClass& EnumField(const char* name,
                          Enum T::*member,
                          const char* (*to_name)(Enum) noexcept,
                          std::optional<Enum> (*from_name)(std::string_view) noexcept,
                          const char* doc) {
    class_.def_property(
        name,
        [member, to_name](const T& o) { return std::string(to_name(o.*member)); },
        [member, from_name, name](T& o, const std::string& value) {
          const std::optional<Enum> parsed = from_name(value);
          if (!parsed) throw py::value_error(std::string(name) + ": unknown value '" + value + "'");
          o.*member = *parsed;
        },
        doc);
    fields_.push_back(name);
    return *this;
  }

  py::class_<T> Finish() {
    class_.attr("_fields") = py::tuple(py::cast(fields_));
    return class_;
  }

 private:
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
  using D = DetectionParameters;
  OptionsClass<D>(m, "DetectionParameters", "RANSAC plane detection (docs/plane_detection.md).")
      .Field("epsilon", &D::epsilon, "inlier tolerance eps (> 0), scene units; None = auto")
      .Field("epsilon_over_noise", &D::epsilon_over_noise, "eps auto: eps / noise scale (0, 20]")
      .Field("relative_epsilon", &D::relative_epsilon, "eps as a fraction of the bbox diagonal")
      .Field("epsilon_fusion_factor", &D::epsilon_fusion_factor, "fusion thickness / eps (>= 1)")
      .Field("theta_fusion_deg", &D::theta_fusion_deg, "fusion angle, degrees (0, 90)")
      .Field("p_fusion", &D::p_fusion, "minimum shared support for a merge [0, 1]")
      .Field("iterations", &D::iterations, "maximum candidate pairs per plane (>= 1)")
      .Field("max_planes", &D::max_planes, "maximum number of planes (>= 1), per block")
      .Field("min_support", &D::min_support, "minimum inlier segments of a plane (>= 2)")
      .Field("support_gap", &D::support_gap, "one plane, one piece: gap, median lengths (0 = off)")
      .Field("collinear_tolerance", &D::collinear_tolerance, "collinear merge, x eps [0, 0.5]")
      .Field("block_size", &D::block_size, "per-block detection cube side (0 = one block)")
      .Field("block_halo", &D::block_halo, "block halo, fraction of its side [0, 0.5)")
      .Field("block_max_segments", &D::block_max_segments, "split blocks above this (0 = never)")
      .Finish();

  using W = EnergyWeights;
  OptionsClass<W>(m, "EnergyWeights", "Weights of the energy terms (docs/reconstruction.md).")
      .Field("textural", &W::textural, "textural primitive term (>= 0)")
      .Field("structural", &W::structural, "structural primitive term (>= 0)")
      .Field("crease", &W::crease, "crease term (>= 0); None = 0.2 interior, 0 exterior")
      .Field("visibility", &W::visibility, "visibility lambda_vis (>= 0)")
      .Field("edge", &W::edge, "edge regularisation (>= 0)")
      .Field("corner", &W::corner, "corner regularisation (>= 0)")
      .Field("area", &W::area, "surface area term (>= 0)")
      .Field("viewpoint_prior", &W::viewpoint_prior, "viewpoint prior per observation (>= 0)")
      .Field("open_seam", &W::open_seam, "blocks engine: surface on plane-less block faces (>= 0)")
      .Finish();

  using S = SolverOptions;
  OptionsClass<S>(m, "SolverOptions", "LP labelling (docs/solver.md).")
      .EnumField("backend",
                 &S::backend,
                 &SolverBackendName,
                 &SolverBackendFromName,
                 "'auto', 'clp', 'maxflow', 'pdhg', 'band', 'cbc', 'clp-barrier', 'blocks' or "
                 "'pdhg-energy'")
      .Field("time_limit_seconds", &S::time_limit_seconds, "solve wall-time limit (0 = none)")
      .Finish();

  using Q = QualityOptions;
  OptionsClass<Q>(m, "QualityOptions", "Figures without ground truth (docs/evaluation.md).")
      .Field("fit_factor", &Q::fit_factor, "a sample fits within fit_factor x eps (> 0)")
      .Field("samples_per_segment", &Q::samples_per_segment, "samples per segment [1, 1024]")
      .Field("min_lines_per_component", &Q::min_lines_per_component, "floating below (>= 0)")
      .Finish();

  using R = ReconstructOptions;
  py::class_<R> reconstruct =
      OptionsClass<R>(m, "ReconstructOptions", "Options of reconstruct().")
          .EnumField("plane_source",
                     &R::planes,
                     &PlaneSourceName,
                     &PlaneSourceFromName,
                     "'detect' or 'given' (C++ field `planes`)")
          .Field("detection", &R::detection, "DetectionParameters")
          .EnumField("scene_mode",
                     &R::scene_mode,
                     &SceneModeName,
                     &SceneModeFromName,
                     "'exterior', 'interior' or 'auto'")
          .Field("weights", &R::weights, "EnergyWeights")
          .Field("sigma", &R::sigma, "evidence scale (> 0); None = median segment length")
          .Field("samples_per_sigma", &R::samples_per_sigma, "evidence samples per sigma")
          .Field("structural_as_textural", &R::structural_as_textural, "ablation")
          .Field("solver", &R::solver, "SolverOptions")
          .EnumField("engine",
                     &R::engine,
                     &ComplexEngineName,
                     &ComplexEngineFromName,
                     "cell complex: 'monolithic' or 'blocks'")
          .Field("block_size", &R::block_size, "blocks engine: base block side (0 = automatic)")
          .Field("block_margin",
                 &R::block_margin,
                 "blocks a plane's support is dilated by [0, 64], fractions allowed")
          .Field("box_margin", &R::box_margin, "box growth, fraction of its extent (0, 10]")
          .Field("measure_quality", &R::measure_quality, "quality figures in the report")
          .Field("remove_floating_fragments",
                 &R::remove_floating_fragments,
                 "drop components holding fewer than quality.min_lines_per_component lines")
          .Field("quality", &R::quality, "QualityOptions")
          .Field("triangulate", &R::triangulate, "triangulate the output faces")
          .Field("merge_coplanar",
                 &R::merge_coplanar,
                 "blocks engine: neighbouring faces of one plane (split by block faces or by "
                 "planes without surface there) merged (not with triangulate)")
          .Field("num_threads", &R::num_threads, "worker threads (0 = automatic)")
          .Field("seed", &R::seed, "seed of every random stream")
          .Finish();
  AddValidate(reconstruct);

  using O = DetectOptions;
  py::class_<O> detect = OptionsClass<O>(m, "DetectOptions", "Options of detect_planes().")
                             .Field("detection", &O::detection, "DetectionParameters")
                             .Field("num_threads", &O::num_threads, "worker threads")
                             .Field("seed", &O::seed, "seed of every random stream")
                             .Finish();
  AddValidate(detect);
}

}  // namespace linesurf::python
