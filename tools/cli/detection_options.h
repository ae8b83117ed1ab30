#pragma once
// The plane-detection options shared by `detect` and `reconstruct` (one declaration each).

#include "engine/detect/detect_planes.h"
#include "tools/cli/option_registry.h"

namespace linesurf::cli {

/// Registers --epsilon, --relative-epsilon, --iterations, --max-planes, --min-support,
/// --collinear-tolerance, --block-size, --block-halo and --block-max-segments, writing into
/// `options` (the seed is the command's --seed).
void RegisterDetectionOptions(OptionRegistry& registry, PlaneDetectionOptions& options);

}  // namespace linesurf::cli
