#pragma once
/// @file surface_quality.h
/// @brief Quality of a reconstruction without ground truth (docs/user/evaluation.md): how well the
/// surface fits the segments that support a plane, whether the surface blocks the sight rays of
/// the observations, its connected components (a component holding fewer than 3 supported
/// lines is a floating fragment) and the planes on which no face lies. Shared by `linesurf evaluate
/// --lines` and the `reconstruct` report.

#include "linesurf/error.h"
#include "linesurf/options.h"
#include "linesurf/result.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"

#include <cstddef>
#include <vector>

namespace linesurf::pipeline {

/// The facade's struct (linesurf/options.h: defaults and rationale; ranges in
/// linesurf/option_schema.h).
using SurfaceQualityOptions = ::linesurf::QualityOptions;

/// The figures (linesurf/result.h).
using ComponentQuality = ::linesurf::ComponentQuality;
using SurfaceQuality = ::linesurf::SurfaceQuality;

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

/// A surface without its floating fragments.
struct FragmentRemoval {
  PolygonMesh mesh;
  std::size_t removed_components = 0;
  double removed_volume = 0.0;  ///< sum of the removed components' volumes (each > 0)
  std::size_t removed_supported_segments = 0;
  /// MeasureSurfaceQuality of `mesh` (the surface returned). When something was removed, only
  /// the segments whose near samples or sight rays met a removed face are measured again; the
  /// others keep the figures of the input surface, which are the kept surface's (up to which of
  /// faces exactly as near a sample is named nearest).
  SurfaceQuality quality;
};

/// @brief `mesh` without the solid components (positive volume) that MeasureSurfaceQuality calls
/// floating fragments (fewer than options.min_lines_per_component supported lines; components as
/// there): their faces and the vertices only they use. The inner shell of a void (negative
/// volume) stays: dropping it would fill the void. The kept faces and vertices keep their order, so a mesh
/// without fragments comes back unchanged. Every component is a closed surface of its own, so
/// what is kept stays closed and 2-manifold. A mesh whose components are all fragments is kept
/// whole (nothing tells which of them is noise).
/// @return the errors of MeasureSurfaceQuality. Deterministic for any thread count.
[[nodiscard]] Expected<FragmentRemoval> RemoveFloatingFragments(
    const PolygonMesh& mesh,
    const Scene& scene,
    double epsilon,
    const SurfaceQualityOptions& options,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
