// The run reports of report.h: one JSON layout for the CLI, Python and C.

#include "linesurf/linesurf.h"

#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "engine/api/options_json.h"

namespace linesurf {
inline namespace v3 {
namespace {

using Json = nlohmann::ordered_json;

/// Components beyond this many are counted, not listed.
constexpr std::size_t kMaxListedComponents = 200;

Json EpsilonJson(const EpsilonEstimate& e) {
  return {{"epsilon", e.epsilon},
          {"source", e.source},
          {"noise_scale", e.noise_scale},
          {"initial_epsilon", e.initial_epsilon},
          {"rounds", e.rounds},
          {"residuals", e.residuals}};
}

Json QualityJson(const SurfaceQuality& q) {
  Json components = Json::array();
  for (std::size_t i = 0; i < q.components.size() && i < kMaxListedComponents; ++i) {
    const ComponentQuality& c = q.components[i];
    components.push_back({{"faces", c.faces},
                          {"volume", c.volume},
                          {"supported_length", c.supported_length},
                          {"supported_segments", c.supported_segments},
                          {"supported_lines", c.supported_lines},
                          {"floating", c.floating}});
  }
  return {{"epsilon", q.epsilon},
          {"fit_distance", q.fit_distance},
          {"supported_segments", q.supported_segments},
          {"supported_length", q.supported_length},
          {"data_fit", q.data_fit},
          {"visibility_consistency", q.visibility_consistency},
          {"visibility_consistency_all_segments", q.visibility_consistency_all},
          {"num_components", q.components.size()},
          {"enclosed_volume", q.enclosed_volume},
          {"largest_component_share", q.largest_component_share},
          {"floating_fragments", q.floating_fragments},
          {"components", std::move(components)},
          {"planes_off_surface", q.planes_off_surface}};
}

Json ValidityJson(const MeshValidity& v) {
  return {{"valid", v.IsValid()},
          {"closed", v.closed},
          {"two_manifold", v.two_manifold},
          {"oriented", v.oriented},
          {"outward", v.outward},
          {"self_intersecting", v.self_intersecting},
          {"num_components", v.num_components},
          {"num_faces", v.num_faces},
          {"num_vertices", v.num_vertices},
          {"num_coincident_vertices", v.num_coincident_vertices},
          {"num_boundary_edges", v.num_boundary_edges},
          {"num_non_manifold_edges", v.num_non_manifold_edges},
          {"num_non_manifold_vertices", v.num_non_manifold_vertices},
          {"num_degenerate_faces", v.num_degenerate_faces},
          {"num_zero_area_faces", v.num_zero_area_faces},
          {"num_non_planar_faces", v.num_non_planar_faces},
          {"num_intersecting_triangle_pairs", v.num_intersecting_triangle_pairs},
          {"num_touching_triangle_pairs", v.num_touching_triangle_pairs},
          {"signed_volume", v.signed_volume}};
}

/// Text that is not UTF-8 (a path in a warning) is written with replacement characters.
std::string Dump(const Json& j) { return j.dump(2, ' ', false, Json::error_handler_t::replace); }

// The writers of the stage structs of ReconstructStats, one each. A stage's numbers go to the
// report's sections by their meaning (`counts` gathers the counts of every stage, in stage
// order; `mesh` the surface's and the fragments'), under the keys of linesurf 1's report.

void WriteInputs(const InputStats& s, Json& report) {
  report["counts"].update(Json{{"input_segments", s.input_segments},
                               {"segments", s.segments},
                               {"viewpoints", s.viewpoints},
                               {"observations", s.observations}});
}

void WriteDetection(const DetectionStats& s, Json& report) {
  report["counts"].update(Json{{"planes", s.planes},
                               {"capped_blocks", s.capped_blocks},
                               {"segments_with_0_planes", s.segments_with_planes[0]},
                               {"segments_with_1_plane", s.segments_with_planes[1]},
                               {"segments_with_2_planes", s.segments_with_planes[2]}});
  report["detection_block_size"] = s.detection_block_size;
  report["epsilon"] = EpsilonJson(s.epsilon);
}

void WriteFrame(const FrameStats& s, Json& report) {
  report["frame"] = Json{{"aligned", s.aligned},
                         {"axes", s.axes},
                         {"up", s.up},
                         {"up_evidence", s.up_evidence},
                         {"up_sign", s.up_sign},
                         {"axis_share", s.axis_share}};
}

void WriteComplex(const ComplexStats& s, Json& report) {
  report["counts"].update(Json{{"planes_in_complex", s.planes_in_complex},
                               {"blocks", s.blocks},
                               {"seam_facets", s.seam_facets},
                               {"crowded_split_faces", s.crowded_split_faces},
                               {"crowded_blocks", s.crowded_blocks},
                               {"cells", s.cells},
                               {"facets", s.facets},
                               {"edges", s.edges},
                               {"vertices", s.vertices}});
  report["engine"] = s.engine;
  report["block_size"] = s.block_size;
  report["block_size_rule"] = {{"automatic", s.block_size_automatic},
                               {"mean_segments_per_block", s.mean_segments_per_block},
                               {"mean_planes_per_block", s.mean_planes_per_block},
                               {"at_floor", s.block_size_at_floor}};
}

void WriteSceneMode(const SceneModeStats& s, Json& report) {
  report["scene_mode"] = s.scene_mode;
  report["scene_mode_reason"] = s.scene_mode_reason;
}

void WriteEnergy(const EnergyStats& s, Json& report) {
  report["counts"].update(Json{{"pair_terms", s.pair_terms},
                               {"structural_groups", s.structural_groups},
                               {"parity_groups", s.parity_groups},
                               {"fixed_cells", s.fixed_cells}});
  report["sigma"] = s.sigma;
  report["crease_weight"] = s.crease_weight;
}

void WriteLabeling(const LabelingStats& s, Json& report) {
  report["counts"].update(Json{{"full_cells", s.full_cells},
                               {"lp_variables", s.lp_variables},
                               {"lp_constraints", s.lp_constraints},
                               {"lp_nonzeros", s.lp_nonzeros}});
  // A lower bound of -infinity (none known) and its gap are null.
  const bool bounded = std::isfinite(s.lower_bound);
  report["solver"] = {{"backend", s.solver_backend},
                      {"method", s.labeling_method},
                      {"status", s.solver_status},
                      {"objective", s.objective},
                      {"rounded_objective", s.rounded_objective},
                      {"relaxed_objective", s.relaxed_objective},
                      {"lower_bound", bounded ? Json(s.lower_bound) : Json()},
                      {"lower_bound_source", s.lower_bound_source},
                      {"gap", bounded ? Json(s.objective - s.lower_bound) : Json()},
                      {"fractional_cells", s.fractional_cells}};
}

void WriteSurface(const SurfaceStats& s, Json& report) {
  report["mesh"].update(Json{{"vertices", s.mesh_vertices},
                             {"faces", s.mesh_faces},
                             {"closed", s.mesh_closed},
                             {"manifold", s.mesh_manifold},
                             {"volume", s.mesh_volume},
                             {"split_vertices", s.split_vertices},
                             {"pinch_cells_relabelled", s.pinch_cells_relabelled},
                             {"split_points", s.split_points},
                             {"pinch_energy_increase", s.pinch_energy_increase}});
}

void WriteFragments(const FragmentStats& s, Json& report) {
  report["mesh"].update(Json{{"removed_fragments", s.removed_fragments},
                             {"removed_fragment_volume", s.removed_fragment_volume},
                             {"removed_fragment_segments", s.removed_fragment_segments}});
}

void WriteQuality(const QualityStats& s, Json& report) {
  if (s.measured) report["quality"] = QualityJson(s);
}

void WriteResources(const ResourceStats& s, Json& report) {
  Json stages = Json::object();
  for (const auto& [name, seconds] : s.stage_seconds) stages[name] = seconds;
  report["stage_seconds"] = std::move(stages);
  report["total_seconds"] = s.total_seconds;
  report["peak_memory_bytes"] = s.peak_memory_bytes;
}

/// The run report's top-level keys in the order it lists them (linesurf 1's order, with
/// stats_version first). A key not listed here follows them, in the order it was written.
constexpr std::array<std::string_view, 21> kReportOrder = {
    "stats_version",
    "options",
    "stage_seconds",
    "total_seconds",
    "counts",
    "engine",
    "block_size",
    "block_size_rule",
    "detection_block_size",
    "scene_mode",
    "scene_mode_reason",
    "sigma",
    "crease_weight",
    "epsilon",
    "frame",
    "quality",
    "solver",
    "mesh",
    "validity",
    "peak_memory_bytes",
    "warnings",
};

Json InReportOrder(Json report) {
  Json ordered = Json::object();
  for (std::string_view key : kReportOrder) {
    if (auto it = report.find(key); it != report.end()) {
      ordered[std::string(key)] = std::move(*it);
    }
  }
  for (auto& [key, value] : report.items()) {
    if (!ordered.contains(key)) ordered[key] = std::move(value);
  }
  return ordered;
}

}  // namespace

std::string ReportJson(const ReconstructResult& result, const ReconstructOptions& options) {
  const ReconstructStats& s = result.stats;
  Json j;
  j["stats_version"] = s.layout_version;
  j["options"] = api::OptionsJson(options);
  j["counts"] = Json::object();
  j["mesh"] = Json::object();
  WriteInputs(s.inputs, j);
  WriteDetection(s.detection, j);
  WriteFrame(s.frame, j);
  WriteComplex(s.complex, j);
  WriteSceneMode(s.scene, j);
  WriteEnergy(s.energy, j);
  WriteLabeling(s.labeling, j);
  WriteSurface(s.surface, j);
  WriteFragments(s.fragments, j);
  WriteQuality(s.quality, j);
  WriteResources(s.resources, j);
  if (Expected<MeshValidity> validity = CheckMesh(result.mesh)) {
    j["validity"] = ValidityJson(*validity);
  }
  j["warnings"] = result.warnings;
  return Dump(InReportOrder(std::move(j)));
}

std::string ReportJson(const DetectResult& result, const DetectOptions& options) {
  const DetectStats& st = result.stats;
  Json j;
  j["options"] = api::OptionsJson(options);
  j["stats"] = {{"input_segments", st.input_segments},
                {"segments", st.segments},
                {"lines", st.lines},
                {"epsilon", st.epsilon},
                {"epsilon_estimate", EpsilonJson(st.epsilon_estimate)},
                {"blocks", st.blocks},
                {"planes_before_fusion", st.planes_before_fusion},
                {"planes", st.planes},
                {"merges", st.merges},
                {"memberships_dropped", st.memberships_dropped},
                {"capped_blocks", st.capped_blocks},
                {"segments_with_0_planes", st.segments_with_0_planes},
                {"segments_with_1_plane", st.segments_with_1_plane},
                {"segments_with_2_planes", st.segments_with_2_planes},
                {"candidates_evaluated", st.candidates_evaluated},
                {"failed_draws", st.failed_draws},
                {"seconds", st.seconds},
                {"seconds_fusion", st.seconds_fusion}};
  Json planes = Json::array();
  for (const PlaneSupportInfo& support : result.support) {
    planes.push_back(
        {{"inlier_count", support.inlier_count}, {"inlier_length", support.inlier_length}});
  }
  j["planes"] = std::move(planes);
  j["warnings"] = result.warnings;
  return Dump(j);
}

std::string ReportJson(const MeshValidity& validity) { return Dump(ValidityJson(validity)); }

std::string ReportJson(const SurfaceQuality& quality) { return Dump(QualityJson(quality)); }

}  // namespace v3
}  // namespace linesurf
