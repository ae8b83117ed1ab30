#pragma once
// The meta file of a synthetic scene (meta.json): spec, true planes, kind and true planes of every
// segment, ground-truth summary. Format in docs/user/synthetic.md.

#include <filesystem>
#include <string>

#include "linesurf/error.h"
#include "tools/gen/synthesize.h"

namespace linesurf::synth {

/// The meta JSON text (deterministic: same scene => same bytes).
[[nodiscard]] std::string SyntheticMetaJson(const SyntheticScene& scene);
/// Writes SyntheticMetaJson(scene) to `path`. Errors name the file.
[[nodiscard]] Status WriteSyntheticMeta(const SyntheticScene& scene,
                                        const std::filesystem::path& path) noexcept;

}  // namespace linesurf::synth
