// The run report of report.h: each stage struct of ReconstructStats under the keys and in the
// places of linesurf 1's report, with stats_version first.

#include "linesurf/report.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace linesurf {
namespace {

using Json = nlohmann::ordered_json;

std::vector<std::string> Keys(const Json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  return keys;
}

// A unit cube, outward, so that CheckMesh gives the report its validity.
Mesh Cube() {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  }
  mesh.face_indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  mesh.face_offsets = {0, 4, 8, 12, 16, 20, 24};
  return mesh;
}

// Distinct values in every stage struct, to find them in the report.
ReconstructResult Result() {
  ReconstructResult r;
  r.mesh = Cube();
  ReconstructStats& s = r.stats;
  s.inputs = {.input_segments = 11, .segments = 10, .viewpoints = 3, .observations = 30};
  s.detection.planes = 6;
  s.detection.capped_blocks = 1;
  s.detection.segments_with_planes = {2, 5, 3};
  s.detection.detection_block_size = 40.0;
  s.detection.epsilon.epsilon = 0.02;
  s.detection.epsilon.source = "probe";
  s.complex.cells = 27;
  s.complex.engine = "blocks";
  s.complex.block_size = 8.0;
  s.complex.block_size_automatic = true;
  s.scene.scene_mode = "exterior";
  s.scene.scene_mode_reason = "auto: 0 of 3 viewpoints enclosed -> exterior";
  s.energy.pair_terms = 54;
  s.energy.sigma = 0.5;
  s.energy.crease_weight = 0.0;
  s.labeling.full_cells = 1;
  s.labeling.solver_backend = "maxflow";
  s.labeling.objective = 2.5;
  s.labeling.lower_bound = -std::numeric_limits<double>::infinity();
  s.labeling.lower_bound_source = "none";
  s.surface.mesh_vertices = 8;
  s.surface.mesh_faces = 6;
  s.surface.mesh_closed = true;
  s.surface.split_vertices = 2;
  s.fragments.removed_fragments = 4;
  s.quality.measured = true;
  s.quality.data_fit = 0.75;
  s.resources.stage_seconds = {{"sanitize", 0.25}, {"detect", 0.5}};
  s.resources.total_seconds = 0.75;
  s.resources.peak_memory_bytes = 1024;
  r.warnings = {"a warning"};
  return r;
}

TEST(ReportJson, TopLevelKeysKeepTheirPlacesWithStatsVersionFirst) {
  const Json report = Json::parse(ReportJson(Result(), ReconstructOptions{}));
  EXPECT_EQ(Keys(report),
            (std::vector<std::string>{"stats_version",
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
                                      "warnings"}));
  EXPECT_EQ(report["stats_version"], kStatsLayoutVersion);
  EXPECT_EQ(report["stats_version"], ReconstructStats{}.layout_version);
}

TEST(ReportJson, CountsOfEveryStageInStageOrder) {
  const Json report = Json::parse(ReportJson(Result(), ReconstructOptions{}));
  EXPECT_EQ(Keys(report["counts"]),
            (std::vector<std::string>{"input_segments",
                                      "segments",
                                      "viewpoints",
                                      "observations",
                                      "planes",
                                      "capped_blocks",
                                      "segments_with_0_planes",
                                      "segments_with_1_plane",
                                      "segments_with_2_planes",
                                      "planes_in_complex",
                                      "blocks",
                                      "seam_facets",
                                      "crowded_split_faces",
                                      "crowded_blocks",
                                      "cells",
                                      "facets",
                                      "edges",
                                      "vertices",
                                      "pair_terms",
                                      "structural_groups",
                                      "parity_groups",
                                      "fixed_cells",
                                      "full_cells",
                                      "lp_variables",
                                      "lp_constraints",
                                      "lp_nonzeros"}));
  EXPECT_EQ(Keys(report["mesh"]),
            (std::vector<std::string>{"vertices",
                                      "faces",
                                      "closed",
                                      "manifold",
                                      "volume",
                                      "split_vertices",
                                      "pinch_cells_relabelled",
                                      "split_points",
                                      "pinch_energy_increase",
                                      "removed_fragments",
                                      "removed_fragment_volume",
                                      "removed_fragment_segments"}));
}

TEST(ReportJson, EachStageStructUnderItsKeys) {
  const Json report = Json::parse(ReportJson(Result(), ReconstructOptions{}));
  const Json& counts = report["counts"];
  EXPECT_EQ(counts["input_segments"], 11);
  EXPECT_EQ(counts["observations"], 30);
  EXPECT_EQ(counts["planes"], 6);
  EXPECT_EQ(counts["capped_blocks"], 1);
  EXPECT_EQ(counts["segments_with_1_plane"], 5);
  EXPECT_EQ(counts["cells"], 27);
  EXPECT_EQ(counts["pair_terms"], 54);
  EXPECT_EQ(counts["full_cells"], 1);
  EXPECT_EQ(report["detection_block_size"], 40.0);
  EXPECT_EQ(report["epsilon"]["source"], "probe");
  EXPECT_EQ(report["engine"], "blocks");
  EXPECT_EQ(report["block_size"], 8.0);
  EXPECT_EQ(report["block_size_rule"]["automatic"], true);
  EXPECT_EQ(report["scene_mode_reason"], "auto: 0 of 3 viewpoints enclosed -> exterior");
  EXPECT_EQ(report["sigma"], 0.5);
  EXPECT_EQ(report["solver"]["backend"], "maxflow");
  EXPECT_EQ(report["solver"]["objective"], 2.5);
  EXPECT_TRUE(report["solver"]["lower_bound"].is_null());  // -infinity: none known
  EXPECT_TRUE(report["solver"]["gap"].is_null());
  EXPECT_EQ(report["mesh"]["faces"], 6);
  EXPECT_EQ(report["mesh"]["closed"], true);
  EXPECT_EQ(report["mesh"]["split_vertices"], 2);
  EXPECT_EQ(report["mesh"]["removed_fragments"], 4);
  EXPECT_EQ(report["quality"]["data_fit"], 0.75);
  EXPECT_EQ(Keys(report["stage_seconds"]), (std::vector<std::string>{"sanitize", "detect"}));
  EXPECT_EQ(report["total_seconds"], 0.75);
  EXPECT_EQ(report["peak_memory_bytes"], 1024);
  EXPECT_EQ(report["validity"]["closed"], true);
  EXPECT_EQ(report["warnings"], Json::array({"a warning"}));
}

TEST(ReportJson, QualityOnlyWhenMeasured) {
  ReconstructResult r = Result();
  r.stats.quality.measured = false;
  const Json report = Json::parse(ReportJson(r, ReconstructOptions{}));
  EXPECT_FALSE(report.contains("quality"));
  EXPECT_EQ(Keys(report).size(), 20u);
}

}  // namespace
}  // namespace linesurf
