#pragma once
/// @file synthetic_files.h
/// @brief A synthetic scene as the three files of `linesurf synth` (lines.json, ground_truth.ply,
/// meta.json; docs/user/synthetic.md), behind plain types: the front end chooses the paths (and
/// writes to temporary names), the scene stays inside.

#include <cstddef>
#include <filesystem>
#include <memory>

#include "linesurf/error.h"
#include "tools/gen/synth_spec.h"

namespace linesurf::synth {

struct SyntheticScene;

/// What a generated scene holds.
struct SyntheticSummary {
  std::size_t segments = 0;
  std::size_t structural = 0;  ///< segments on a sharp edge of the ground truth
  std::size_t textural = 0;    ///< segments on a face
  std::size_t outliers = 0;
  std::size_t viewpoints = 0;
  std::size_t true_planes = 0;
  std::size_t ground_truth_faces = 0;
};

class SyntheticFiles {
 public:
  /// Builds the scene of `spec` (Synthesize) on `num_threads` threads (0: all). The bytes do not
  /// depend on the thread count. Errors: kInvalidOptions for a bad spec.
  [[nodiscard]] static Expected<SyntheticFiles> Generate(const SynthSpec& spec,
                                                         int num_threads) noexcept;

  /// The reference JSON of the segments, views and true planes (plane_index = true planes).
  [[nodiscard]] Status WriteLines(const std::filesystem::path& path) const noexcept;
  /// The ground-truth solid as a mesh (format by extension).
  [[nodiscard]] Status WriteGroundTruth(const std::filesystem::path& path) const noexcept;
  /// The meta JSON (spec, true planes, kind and true planes of every segment).
  [[nodiscard]] Status WriteMeta(const std::filesystem::path& path) const noexcept;

  [[nodiscard]] SyntheticSummary Summary() const noexcept;

  SyntheticFiles(SyntheticFiles&&) noexcept;
  SyntheticFiles& operator=(SyntheticFiles&&) noexcept;
  ~SyntheticFiles();

 private:
  explicit SyntheticFiles(std::unique_ptr<SyntheticScene> scene) noexcept;
  std::unique_ptr<SyntheticScene> scene_;
};

}  // namespace linesurf::synth
