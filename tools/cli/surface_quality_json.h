#pragma once
// The figures without ground truth (engine/pipeline/surface_quality.h) as written by `evaluate
// --lines` and the `reconstruct` report, and their one-paragraph summary (one definition).

#include "engine/pipeline/surface_quality.h"

#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {

/// Components beyond this many are summed up in the JSON, not listed one by one.
inline constexpr std::size_t kMaxListedComponents = 200;

nlohmann::json SurfaceQualityJson(const pipeline::SurfaceQuality& q);

/// A few lines for stderr/stdout, each starting with `prefix`.
std::string SurfaceQualitySummary(const pipeline::SurfaceQuality& q, const std::string& prefix);

}  // namespace linesurf::cli
