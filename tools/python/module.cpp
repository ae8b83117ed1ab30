// _linesurf: the compiled half of the Python package linesurf (linesurf/__init__.py is the
// public half: keyword options, result classes). Facade only: linesurf/linesurf.h.

#include "linesurf/linesurf.h"

#include "tools/python/arrays.h"
#include "tools/python/bind_options.h"
#include "tools/python/errors.h"
#include "tools/python/python_run_control.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace linesurf::python {
namespace {

// The input arrays of one call, (segments, viewpoints, observations, planes, memberships) any
// of which may be None, copied into facade types (owned for the call's duration).
SceneData ReadArrays(const py::tuple& arrays) {
  if (arrays.size() != 5) throw py::type_error("expected 5 scene arrays");
  SceneData scene;
  scene.segments = SegmentsFromArray(arrays[0]);
  scene.viewpoints = PointsFromArray(arrays[1], "viewpoints");
  scene.observations = ObservationsFromArray(arrays[2]);
  scene.planes = PlanesFromArray(arrays[3]);
  scene.memberships = MembershipsFromArray(arrays[4]);
  return scene;
}

py::dict MeshToDict(const Mesh& mesh) {
  py::dict d;
  d["vertices"] = PointsToArray(mesh.vertices);
  d["face_offsets"] = IndicesToArray(mesh.face_offsets);
  d["face_indices"] = IndicesToArray(mesh.face_indices);
  return d;
}

/// A report of report.h as Python objects (dicts, lists, numbers, strings).
py::object ParsedReport(const std::string& json) {
  return py::module_::import("json").attr("loads")(json);
}

py::dict ResultToDict(const ReconstructResult& result, const ReconstructOptions& options) {
  py::dict d;
  d["mesh"] = MeshToDict(result.mesh);
  d["planes"] = PlanesToArray(result.planes);
  d["memberships"] = MembershipsToArray(result.memberships);
  d["report"] = ParsedReport(ReportJson(result, options));
  d["warnings"] = result.warnings;
  return d;
}

py::dict ReconstructArrays(const py::tuple& arrays,
                           const ReconstructOptions& options,
                           py::object progress,
                           py::object log) {
  const SceneData scene = ReadArrays(arrays);
  PythonRunControl control(std::move(progress), std::move(log));
  return ResultToDict(ValueOrRaise(control.Run<ReconstructResult>(
                          [&](const RunControl& c) { return Reconstruct(scene.View(), options, c); })),
                      options);
}

std::unique_ptr<Reconstruction> PrepareArrays(const py::tuple& arrays,
                                              const ReconstructOptions& options,
                                              py::object progress,
                                              py::object log) {
  const SceneData scene = ReadArrays(arrays);
  PythonRunControl control(std::move(progress), std::move(log));
  return std::make_unique<Reconstruction>(ValueOrRaise(control.Run<Reconstruction>(
      [&](const RunControl& c) { return Reconstruction::Prepare(scene.View(), options, c); })));
}

py::dict SolvePrepared(const Reconstruction& prepared,
                       const EnergyWeights& weights,
                       py::object progress,
                       py::object log) {
  PythonRunControl control(std::move(progress), std::move(log));
  ReconstructOptions options = prepared.Options();
  options.weights = weights;
  return ResultToDict(ValueOrRaise(control.Run<ReconstructResult>(
                          [&](const RunControl& c) { return prepared.Solve(weights, c); })),
                      options);
}

py::dict DetectArrays(const py::tuple& arrays,
                      const DetectOptions& options,
                      py::object progress,
                      py::object log) {
  const SceneData scene = ReadArrays(arrays);
  PythonRunControl control(std::move(progress), std::move(log));
  const DetectResult result = ValueOrRaise(control.Run<DetectResult>(
      [&](const RunControl& c) { return DetectPlanes(scene.View(), options, c); }));
  std::vector<std::uint32_t> inlier_count;
  std::vector<double> inlier_length;
  for (const PlaneSupportInfo& s : result.support) {
    inlier_count.push_back(s.inlier_count);
    inlier_length.push_back(s.inlier_length);
  }
  py::dict d;
  d["planes"] = PlanesToArray(result.planes);
  d["inlier_count"] = IndicesToArray(inlier_count);
  d["inlier_length"] =
      py::array_t<double>(static_cast<py::ssize_t>(inlier_length.size()), inlier_length.data());
  d["memberships"] = MembershipsToArray(result.memberships);
  d["report"] = ParsedReport(ReportJson(result, options));
  d["warnings"] = result.warnings;
  return d;
}

std::optional<SceneFormat> SceneFormatFromName(const std::string& name) {
  if (name == "auto") return SceneFormat::kAuto;
  if (name == "json") return SceneFormat::kReferenceJson;
  if (name == "line3dpp") return SceneFormat::kLine3dpp;
  if (name == "obj") return SceneFormat::kObjLines;
  if (name == "limap") return SceneFormat::kLimapTracks;
  return std::nullopt;
}

py::dict ReadSceneArrays(const std::string& path,
                         const std::string& nvm,
                         const std::string& colmap,
                         const std::string& format) {
  ReadOptions options;
  const std::optional<SceneFormat> parsed = SceneFormatFromName(format);
  if (!parsed) {
    throw py::value_error("format: unknown value '" + format +
                          "' (auto, json, line3dpp, limap or obj)");
  }
  options.format = *parsed;
  options.nvm = nvm;
  options.colmap = colmap;
  Expected<ReadSceneResult> read = [&] {
    py::gil_scoped_release release;
    return ReadScene(path, options);
  }();
  const ReadSceneResult result = ValueOrRaise(std::move(read));
  const SceneData& s = result.scene;
  py::dict d;
  d["segments"] = SegmentsToArray(s.segments);
  d["viewpoints"] = PointsToArray(s.viewpoints);
  d["observations"] = ObservationsToArray(s.observations);
  d["planes"] = PlanesToArray(s.planes);
  d["memberships"] = MembershipsToArray(s.memberships);
  d["warnings"] = result.warnings;
  return d;
}

void WriteMeshArrays(const std::string& path,
                     const py::object& vertices,
                     const py::object& face_offsets,
                     const py::object& face_indices,
                     const MeshWriteOptions& options) {
  Mesh mesh;
  mesh.vertices = PointsFromArray(vertices, "vertices");
  mesh.face_offsets = IndicesFromArray(face_offsets, "face_offsets");
  mesh.face_indices = IndicesFromArray(face_indices, "face_indices");
  Status written = [&] {
    py::gil_scoped_release release;
    return WriteMesh(path, mesh, options);
  }();
  if (!written) RaiseError(written.error());
}

/// One work unit (linesurf/work_units.h) with the GIL released: the worker's other threads
/// (Dask's heartbeats, other units) go on while it runs.
py::dict RunWorkUnitInDirectory(const std::string& work_dir, const std::string& unit,
                                int num_threads) {
  Expected<WorkUnitInfo> run = [&] {
    py::gil_scoped_release release;
    return RunWorkUnit(work_dir, unit, num_threads);
  }();
  const WorkUnitInfo info = ValueOrRaise(std::move(run));
  py::dict out;
  out["id"] = info.id;
  out["status"] = info.status;
  out["reason"] = info.reason;
  out["seconds"] = info.seconds;
  return out;
}

}  // namespace
}  // namespace linesurf::python

PYBIND11_MODULE(_linesurf, m) {
  namespace py = pybind11;
  using namespace linesurf::python;
  m.doc() = "linesurf facade bindings; use the package linesurf, not this module.";
  m.attr("__version__") = linesurf::LibraryVersion();
  BindOptions(m);
  py::class_<linesurf::MeshWriteOptions>(m, "MeshWriteOptions")
      .def(py::init<>())
      .def_readwrite("ascii", &linesurf::MeshWriteOptions::ascii)
      .def_readwrite("triangulate", &linesurf::MeshWriteOptions::triangulate);
  m.def("reconstruct", &ReconstructArrays);
  m.def("detect_planes", &DetectArrays);
  py::class_<linesurf::Reconstruction, std::unique_ptr<linesurf::Reconstruction>>(
      m, "Reconstruction", "A prepared reconstruction (planes and cell complex).")
      .def_property_readonly("options",
                             [](const linesurf::Reconstruction& r) {
                               return linesurf::ReconstructOptions(r.Options());
                             })
      .def("solve", &SolvePrepared);
  m.def("prepare", &PrepareArrays);
  m.def("read_scene", &ReadSceneArrays);
  m.def("write_mesh", &WriteMeshArrays);
  m.def("run_work_unit", &RunWorkUnitInDirectory, py::arg("work_dir"), py::arg("unit"),
        py::arg("num_threads"));
}
