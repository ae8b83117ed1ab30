#pragma once
/// @file result.h
/// @brief Results of the facade calls: they own their data and carry their numbers (stats) and
/// warnings ("412 segments dropped: zero or near-zero length"). World coordinates.

#include "linesurf/export.h"
#include "linesurf/stats.h"
#include "linesurf/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace linesurf {
inline namespace v3 {

/// Numbers of a reconstruction, one struct per stage (stats.h; docs/design/reconstruction.md
/// explains each, docs/design/options_and_reports.md how the layout grows). The engine fills this
/// very struct (pipeline::RunStats), each stage's struct in one place from that stage's result.
struct ReconstructStats {
  /// The layout of this struct: kStatsLayoutVersion of the library that filled it.
  int layout_version = kStatsLayoutVersion;
  InputStats inputs;
  DetectionStats detection;
  ComplexStats complex;
  SceneModeStats scene;
  EnergyStats energy;
  LabelingStats labeling;
  SurfaceStats surface;
  FragmentStats fragments;
  QualityStats quality;
  ResourceStats resources;
  FrameStats frame;
};

/// What a mesh is as the boundary of solids: the classes of ISO 19107 / val3dity that GIS and
/// BIM validators check (docs/user/formats.md, "Validity"). Connectivity is by vertex index: two
/// vertices at one position are two vertices, counted in num_coincident_vertices. CheckMesh
/// fills it; Reconstruct refuses a result that is not closed, 2-manifold at its edges, oriented,
/// free of degenerate and non-planar faces and of self-intersection, and warns of the rest.
struct MeshValidity {
  /// No boundary edge: every undirected edge is used by exactly two faces (and the mesh has faces).
  bool closed = false;
  /// Every edge is used by at most two faces and the faces around every vertex form one fan.
  bool two_manifold = false;
  /// Every edge used by two faces is traversed once in each direction.
  bool oriented = false;
  /// Closed, oriented and with positive signed volume (normals point outwards).
  bool outward = false;
  /// num_intersecting_triangle_pairs > 0.
  bool self_intersecting = false;
  /// Connected components, faces linked through shared edges.
  std::size_t num_components = 0;
  std::size_t num_faces = 0;
  std::size_t num_vertices = 0;
  /// Vertices at the bit-identical position of another vertex (split where parts touch).
  std::size_t num_coincident_vertices = 0;
  std::size_t num_boundary_edges = 0;
  std::size_t num_non_manifold_edges = 0;    ///< used by more than two faces
  std::size_t num_non_manifold_vertices = 0;  ///< whose incident faces form several fans
  std::size_t num_degenerate_faces = 0;       ///< fewer than 3 distinct vertices, or one twice
  /// Faces thinner than 1e-9 of the bounding-box diagonal (twice the area over the longest
  /// edge): zero-area faces up to the rounding of their vertices.
  std::size_t num_zero_area_faces = 0;
  /// Faces with a vertex farther than 1e-9 of the bounding-box diagonal from the plane of the
  /// face (Newell's normal through the centroid).
  std::size_t num_non_planar_faces = 0;
  /// Pairs of triangles of the triangulated faces that intersect other than at a shared edge
  /// or vertex (CGAL self_intersections), and have no corner position in common.
  std::size_t num_intersecting_triangle_pairs = 0;
  /// Pairs that meet at a corner position without sharing the vertex (coincident copies):
  /// parts touching at split vertices.
  std::size_t num_touching_triangle_pairs = 0;
  /// Signed volume enclosed (divergence theorem over the faces); meaningful when closed.
  double signed_volume = 0.0;
  double area = 0.0;

  /// Every class clear: closed, 2-manifold, oriented, and no count above is non-zero.
  [[nodiscard]] bool IsValid() const noexcept {
    return num_faces > 0 && closed && two_manifold && oriented && !self_intersecting &&
           num_coincident_vertices == 0 && num_degenerate_faces == 0 &&
           num_zero_area_faces == 0 && num_non_planar_faces == 0 &&
           num_touching_triangle_pairs == 0;
  }
};

/// Result of Reconstruct and Reconstruction::Solve.
struct ReconstructResult {
  /// The closed, 2-manifold surface, faces oriented from full to empty space.
  Mesh mesh;
  /// The planes used (detected or the given ones that survived sanitation).
  std::vector<Plane> planes;
  /// Plane memberships: `segment` indexes the INPUT segments, `plane` indexes `planes`; sorted by
  /// segment, then plane. Segments dropped by sanitation have none.
  std::vector<Membership> memberships;
  ReconstructStats stats;
  /// Sanitation, detection, complex and evidence warnings, one sentence each.
  std::vector<std::string> warnings;
};

/// Support of one detected plane.
struct PlaneSupportInfo {
  std::uint32_t inlier_count = 0;
  double inlier_length = 0.0;  ///< total length of the inlier segments
};

/// Numbers of a plane detection.
struct DetectStats {
  std::size_t input_segments = 0;
  std::size_t segments = 0;          ///< after sanitation
  std::int64_t lines = 0;            ///< distinct lines (collinear parts merged)
  double epsilon = 0.0;              ///< the eps used
  EpsilonEstimate epsilon_estimate;  ///< how it was chosen
  std::int64_t blocks = 0;
  std::int32_t planes_before_fusion = 0;
  std::int32_t planes = 0;
  std::int32_t merges = 0;
  std::int64_t memberships_dropped = 0;  ///< by the at-most-2 rule across blocks
  std::int64_t capped_blocks = 0;        ///< blocks stopped at max_planes, unsplit
  std::int64_t segments_with_0_planes = 0;
  std::int64_t segments_with_1_plane = 0;
  std::int64_t segments_with_2_planes = 0;
  std::int64_t candidates_evaluated = 0;
  std::int64_t failed_draws = 0;
  double seconds = 0.0;
  double seconds_fusion = 0.0;
};

/// Result of DetectPlanes.
struct DetectResult {
  std::vector<Plane> planes;
  /// One per plane.
  std::vector<PlaneSupportInfo> support;
  /// `segment` indexes the INPUT segments; sorted by segment, then plane.
  std::vector<Membership> memberships;
  DetectStats stats;
  /// Sanitation warnings, then the plane-cap warning when a block stopped at max_planes.
  std::vector<std::string> warnings;
};

/// Result of DetectScenePlanes.
struct DetectedScene {
  /// The sanitised scene holding the detected planes and memberships (the input's own planes
  /// dropped), world coordinates, residuals and extra fields kept: what `linesurf detect -o`
  /// writes.
  SceneData scene;
  /// The planes, support, memberships (indexing the input segments), stats and warnings, as
  /// DetectPlanes returns them.
  DetectResult detection;
  /// Planes the input carried (ignored by detection).
  std::size_t given_planes = 0;
};

/// Result of SanitizeScene.
struct SanitizedScene {
  /// The repaired scene, world coordinates.
  SceneData scene;
  /// Per segment of `scene`, its index in the input (ascending).
  std::vector<std::uint32_t> input_segment;
  /// One sentence per kind of repair, e.g. "412 segments dropped: zero or near-zero length".
  std::vector<std::string> warnings;
};

/// Result of ReadScene.
struct ReadSceneResult {
  SceneData scene;
  /// What the reader fixed or ignored, one sentence each.
  std::vector<std::string> warnings;
};

}  // namespace v3
}  // namespace linesurf
