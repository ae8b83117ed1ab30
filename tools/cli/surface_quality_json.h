#pragma once
// The figures without ground truth (linesurf::SurfaceQuality) as written by `evaluate
// --lines` and the `reconstruct` report, and their one-paragraph summary (one definition).

#include "linesurf/result.h"

#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {

/// Components beyond this many are summed up in the JSON, not listed one by one.
inline constexpr std::size_t kMaxListedComponents = 200;

nlohmann::json SurfaceQualityJson(const SurfaceQuality& q);

/// A few lines for stderr/stdout, each starting with `prefix`.
std::string SurfaceQualitySummary(const SurfaceQuality& q, const std::string& prefix);

}  // namespace linesurf::cli
