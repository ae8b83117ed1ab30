#pragma once
/// @file evaluate_mesh.h
/// @brief Compares a reconstructed mesh with a ground-truth mesh (Langlois et al. 2019, Sec. 5):
/// area-uniform samples on both, exact point-to-surface distances both ways, precision and
/// completeness as the share of samples under each threshold, plus topology of the result.

#include <cstdint>
#include <optional>
#include <vector>

#include "linesurf/error.h"
#include "linesurf/evaluation.h"

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/run_context.h"

namespace linesurf::pipeline {

/// The facade's structs (linesurf/evaluation.h: fields, ranges, meaning).
using EvaluationOptions = ::linesurf::EvaluationOptions;
using DistanceStats = ::linesurf::DistanceStats;
using EvaluationResult = ::linesurf::EvaluationResult;

/// EvaluationOptions::Validate (the facade's): kInvalidOptions naming the first field out of its
/// range.
[[nodiscard]] Status ValidateEvaluationOptions(const EvaluationOptions& options) noexcept;

/// @brief Evaluates `result` against `ground_truth` (both in the same frame and units).
/// @param visible_from when given, completeness only counts ground-truth samples that some
///   viewpoint sees unoccluded by the ground truth (the segment viewpoint -> sample hits no face
///   before the sample).
/// @param ctx threads (an arena of ctx->num_threads; options.num_threads is the facade's) and cancellation; may be null.
/// @return kInvalidOptions, kInvalidInput (a mesh without area, bad indices), kCancelled.
/// Thread-safe, deterministic (bit-identical for any thread count), never throws.
Expected<EvaluationResult> EvaluateMesh(const PolygonMesh& result, const PolygonMesh& ground_truth,
                                        const EvaluationOptions& options,
                                        const std::optional<std::vector<Vec3>>& visible_from =
                                            std::nullopt,
                                        const RunContext* ctx = nullptr) noexcept;

}  // namespace linesurf::pipeline
