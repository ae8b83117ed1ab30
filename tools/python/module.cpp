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

#define LINESURF_REPORT(field) report[#field] = stats.field

py::dict ReportOf(const EpsilonEstimate& stats) {
  py::dict report;
  LINESURF_REPORT(epsilon);
  LINESURF_REPORT(source);
  LINESURF_REPORT(noise_scale);
  LINESURF_REPORT(initial_epsilon);
  LINESURF_REPORT(rounds);
  LINESURF_REPORT(residuals);
  return report;
}

py::dict ReportOf(const ComponentQuality& stats) {
  py::dict report;
  LINESURF_REPORT(faces);
  LINESURF_REPORT(volume);
  LINESURF_REPORT(supported_length);
  LINESURF_REPORT(supported_segments);
  LINESURF_REPORT(supported_lines);
  LINESURF_REPORT(floating);
  return report;
}

py::dict ReportOf(const SurfaceQuality& stats) {
  py::dict report;
  LINESURF_REPORT(epsilon);
  LINESURF_REPORT(fit_distance);
  LINESURF_REPORT(supported_segments);
  LINESURF_REPORT(supported_length);
  LINESURF_REPORT(data_fit);
  LINESURF_REPORT(visibility_consistency);
  LINESURF_REPORT(visibility_consistency_all);
  py::list components;
  for (const ComponentQuality& c : stats.components) components.append(ReportOf(c));
  report["components"] = components;
  LINESURF_REPORT(enclosed_volume);
  LINESURF_REPORT(largest_component_share);
  LINESURF_REPORT(floating_fragments);
  LINESURF_REPORT(planes_off_surface);
  return report;
}

py::dict ReportOf(const ReconstructStats& stats) {
  py::dict report;
  py::list stages;
  for (const auto& [stage, seconds] : stats.stage_seconds)
    stages.append(py::make_tuple(stage, seconds));
  report["stage_seconds"] = stages;
  LINESURF_REPORT(total_seconds);
  LINESURF_REPORT(input_segments);
  LINESURF_REPORT(segments);
  LINESURF_REPORT(viewpoints);
  LINESURF_REPORT(observations);
  LINESURF_REPORT(planes);
  LINESURF_REPORT(capped_blocks);
  report["epsilon"] = ReportOf(stats.epsilon);
  report["segments_with_planes"] = py::make_tuple(
      stats.segments_with_planes[0], stats.segments_with_planes[1], stats.segments_with_planes[2]);
  LINESURF_REPORT(planes_in_complex);
  LINESURF_REPORT(engine);
  LINESURF_REPORT(block_size);
  LINESURF_REPORT(block_size_automatic);
  LINESURF_REPORT(mean_segments_per_block);
  LINESURF_REPORT(mean_planes_per_block);
  LINESURF_REPORT(block_size_at_floor);
  LINESURF_REPORT(detection_block_size);
  LINESURF_REPORT(blocks);
  LINESURF_REPORT(seam_facets);
  LINESURF_REPORT(crowded_split_faces);
  LINESURF_REPORT(crowded_blocks);
  LINESURF_REPORT(cells);
  LINESURF_REPORT(facets);
  LINESURF_REPORT(edges);
  LINESURF_REPORT(vertices);
  LINESURF_REPORT(scene_mode);
  LINESURF_REPORT(scene_mode_reason);
  LINESURF_REPORT(sigma);
  LINESURF_REPORT(crease_weight);
  LINESURF_REPORT(pair_terms);
  LINESURF_REPORT(structural_groups);
  LINESURF_REPORT(parity_groups);
  LINESURF_REPORT(fixed_cells);
  LINESURF_REPORT(lp_variables);
  LINESURF_REPORT(lp_constraints);
  LINESURF_REPORT(lp_nonzeros);
  LINESURF_REPORT(solver_backend);
  LINESURF_REPORT(solver_status);
  LINESURF_REPORT(objective);
  LINESURF_REPORT(relaxed_objective);
  LINESURF_REPORT(rounded_objective);
  LINESURF_REPORT(lower_bound);
  LINESURF_REPORT(lower_bound_source);
  LINESURF_REPORT(labeling_method);
  LINESURF_REPORT(fractional_cells);
  LINESURF_REPORT(full_cells);
  LINESURF_REPORT(mesh_vertices);
  LINESURF_REPORT(mesh_faces);
  LINESURF_REPORT(mesh_closed);
  LINESURF_REPORT(mesh_manifold);
  LINESURF_REPORT(mesh_volume);
  LINESURF_REPORT(split_vertices);
  LINESURF_REPORT(removed_fragments);
  LINESURF_REPORT(removed_fragment_volume);
  LINESURF_REPORT(removed_fragment_segments);
  if (stats.quality_measured) report["quality"] = ReportOf(stats.quality);
  LINESURF_REPORT(peak_memory_bytes);
  return report;
}

py::dict ReportOf(const DetectStats& stats) {
  py::dict report;
  LINESURF_REPORT(input_segments);
  LINESURF_REPORT(segments);
  LINESURF_REPORT(lines);
  LINESURF_REPORT(epsilon);
  report["epsilon_estimate"] = ReportOf(stats.epsilon_estimate);
  LINESURF_REPORT(blocks);
  LINESURF_REPORT(planes_before_fusion);
  LINESURF_REPORT(planes);
  LINESURF_REPORT(merges);
  LINESURF_REPORT(memberships_dropped);
  LINESURF_REPORT(capped_blocks);
  LINESURF_REPORT(segments_with_0_planes);
  LINESURF_REPORT(segments_with_1_plane);
  LINESURF_REPORT(segments_with_2_planes);
  LINESURF_REPORT(candidates_evaluated);
  LINESURF_REPORT(failed_draws);
  LINESURF_REPORT(seconds);
  LINESURF_REPORT(seconds_fusion);
  return report;
}

#undef LINESURF_REPORT

py::dict ResultToDict(const ReconstructResult& result) {
  py::dict d;
  d["mesh"] = MeshToDict(result.mesh);
  d["planes"] = PlanesToArray(result.planes);
  d["memberships"] = MembershipsToArray(result.memberships);
  d["report"] = ReportOf(result.stats);
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
      [&](const RunControl& c) { return Reconstruct(scene.View(), options, c); })));
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
  return ResultToDict(ValueOrRaise(control.Run<ReconstructResult>(
      [&](const RunControl& c) { return prepared.Solve(weights, c); })));
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
  d["report"] = ReportOf(result.stats);
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
}
