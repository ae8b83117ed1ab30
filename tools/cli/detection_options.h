#pragma once
// The plane-detection options shared by `detect` and `reconstruct` (one declaration each).

#include "linesurf/options.h"
#include "linesurf/result.h"

#include "tools/cli/option_registry.h"

#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {

/// Registers --epsilon, --relative-epsilon, --iterations, --max-planes, --min-support, --support-gap,
/// --collinear-tolerance, --block-size, --block-halo and --block-max-segments, writing into
/// `options` (the seed is the command's --seed). The three block flags get `block_prefix` in
/// front (`reconstruct` uses "detect-": its --block-size is the block engine's).
void RegisterDetectionOptions(OptionRegistry& registry,
                              DetectionParameters& options,
                              const std::string& block_prefix = "");

/// How eps was chosen, as written in run reports.
nlohmann::json EpsilonJson(const EpsilonEstimate& estimate);

}  // namespace linesurf::cli
