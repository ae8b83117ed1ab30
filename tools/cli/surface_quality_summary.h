#pragma once
// The one-paragraph summary of the figures without ground truth (linesurf::SurfaceQuality) that
// `evaluate --lines` and `reconstruct` print.

#include "linesurf/result.h"

#include <string>

namespace linesurf::cli {

/// A few lines for stderr/stdout, each starting with `prefix`.
std::string SurfaceQualitySummary(const SurfaceQuality& q, const std::string& prefix);

}  // namespace linesurf::cli
