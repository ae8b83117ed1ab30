#pragma once
/// @file quality_against_lines.h
/// @brief The figures without ground truth (surface_quality.h) of any mesh against a scene's
/// segments: the scene's own planes when it gives them with memberships, detected ones otherwise
/// (`linesurf evaluate --lines`, the facade's MeasureSurfaceQuality).

#include "linesurf/error.h"

#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "engine/detect/detect_planes.h"
#include "engine/pipeline/surface_quality.h"

namespace linesurf::pipeline {

/// @brief Sanitises `lines`, detects planes with `detection` unless it has planes and
/// memberships, resolves eps (`detection.epsilon`, or estimated) and measures `mesh`, given in
/// the world frame of `lines`, against the sanitised scene.
/// @return the errors of sanitation, detection and MeasureSurfaceQuality. Deterministic for any
/// thread count; never throws.
[[nodiscard]] Expected<SurfaceQuality> MeasureQualityAgainstLines(
    const PolygonMesh& mesh,
    Scene lines,
    const PlaneDetectionOptions& detection,
    const RunContext& ctx) noexcept;

}  // namespace linesurf::pipeline
