#pragma once
// The plane-detection flags shared by `detect` and `reconstruct` (one definition, no copies).

#include <optional>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "engine/detect/detect_planes.h"

namespace linesurf::cli {

/// Adds --epsilon, --relative-epsilon, --iterations, --max-planes, --min-support,
/// --collinear-tolerance, --block-size, --block-halo and --block-max-segments, writing into
/// `options` and `relative_epsilon` (copy the latter into options.relative_epsilon after parsing).
void AddDetectionOptions(CLI::App& sub, PlaneDetectionOptions& options,
                         std::optional<double>& relative_epsilon);

/// The detection options as written in run reports (`detect --report`, `reconstruct --report`).
nlohmann::json DetectionOptionsJson(const PlaneDetectionOptions& options);

}  // namespace linesurf::cli
