#pragma once
/// @file surface_quality.h
/// @brief Quality of a reconstruction without ground truth (docs/evaluation.md): how well the
/// surface fits the segments that support a plane, whether the surface blocks the sight rays of
/// the observations, its connected components (a component holding fewer than 3 supported
/// lines is a floating fragment) and the planes on which no face lies. Shared by `linesurf evaluate
/// --lines` and the `reconstruct` report.

#include "linesurf/error.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"

#include <cstddef>
#include <vector>

namespace linesurf::pipeline {

struct SurfaceQualityOptions {
  /// A segment sample lies on the surface when within fit_factor x eps of it (> 0; 2, the width
  /// of the inlier slab plus the surface's own tolerance).
  double fit_factor = 2.0;
  /// Each segment is integrated at this many midpoint samples of equal sub-segments (1..1024).
  /// 8: shares to 1/8 of a segment, whatever the units.
  int samples_per_segment = 8;
  /// A component holding fewer distinct supported lines than this is a floating fragment (>= 0;
  /// 3, the fewest a detected plane has): a slab on a plane of two outliers holds a few segments,
  /// and with a residual split each of its lines counts once, not once per camera.
  int min_lines_per_component = 3;

  [[nodiscard]] Status Validate() const;
};

/// One connected component of the surface.
struct ComponentQuality {
  std::size_t faces = 0;
  /// Signed volume (positive when outward, negative for a cavity or an interior scene's room).
  double volume = 0.0;
  /// Length of supported-segment samples within the fit distance whose nearest face is here.
  double supported_length = 0.0;
  /// Supported segments whose greater share of near samples lies on this component.
  std::size_t supported_segments = 0;
  /// Distinct lines among them (collinear parts of one line count once).
  std::size_t supported_lines = 0;
  /// Holds fewer than SurfaceQualityOptions::min_lines_per_component lines.
  bool floating = false;
};

struct SurfaceQuality {
  double epsilon = 0.0;                ///< eps the figures were measured with (scene units)
  double fit_distance = 0.0;           ///< fit_factor x eps
  std::size_t supported_segments = 0;  ///< segments on at least one plane
  double supported_length = 0.0;       ///< their total length
  /// Share of the supported length within fit_distance of the surface, [0, 1].
  double data_fit = 0.0;
  /// Share of the (supported segment, viewpoint) sight-ray length not blocked by the surface
  /// before the segment, [0, 1]; 1 without views. A ray to a sample is blocked by a face it
  /// crosses unless the sample lies within fit_distance of that face's plane (the face it lies
  /// on: noise must not count as occlusion, even for grazing rays).
  double visibility_consistency = 0.0;
  /// The same over every segment with views (outliers included).
  double visibility_consistency_all = 0.0;
  /// Components, largest |volume| first (ties by first face).
  std::vector<ComponentQuality> components;
  double enclosed_volume = 0.0;          ///< sum of the components' |volume|
  double largest_component_share = 0.0;  ///< |volume| of the largest / enclosed_volume
  std::size_t floating_fragments = 0;
  /// Planes of the scene on which no face of positive area lies (all its vertices within eps).
  std::vector<PlaneId> planes_off_surface;
};

/// @brief Measures `mesh` against `scene`'s segments, views, planes and memberships (same frame).
/// Components are faces linked through shared vertices, vertices at the same position counting
/// as one, so the pieces the extraction split at a pinch stay one solid.
/// @param epsilon the detection tolerance (scene units, > 0).
/// @return kInvalidOptions, kInvalidInput (no face with area, index out of range, memberships
/// not one per segment), kCancelled. Deterministic for any thread count; never throws.
/// Cost: one closest-point query per sample and one segment query per sample and view (CGAL
/// AABB tree over the triangulated faces).
[[nodiscard]] Expected<SurfaceQuality> MeasureSurfaceQuality(const PolygonMesh& mesh,
                                                             const Scene& scene,
                                                             double epsilon,
                                                             const SurfaceQualityOptions& options,
                                                             const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
