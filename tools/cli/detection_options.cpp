#include "tools/cli/detection_options.h"

namespace linesurf::cli {

void AddDetectionOptions(CLI::App& sub, PlaneDetectionOptions& options,
                         std::optional<double>& relative_epsilon) {
  sub.add_option("--epsilon", options.epsilon, "Inlier tolerance eps, scene units")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub.add_option("--relative-epsilon", relative_epsilon,
                 "eps as a fraction of the scene diagonal (overrides --epsilon)");
  sub.add_option("--iterations", options.iterations, "Max candidate pairs per plane")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub.add_option("--max-planes", options.max_planes,
                 "Max number of planes (per block with --block-size)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub.add_option("--min-support", options.min_support, "Min inlier segments per plane")
      ->capture_default_str();
  sub.add_option("--collinear-tolerance", options.collinear_tolerance,
                 "Segments on one line within this x eps are detected as one (0 = off)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  sub.add_option("--block-size", options.block_size,
                 "Per-block detection: cube side, scene units (0 = whole scene at once)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub.add_option("--block-halo", options.block_halo, "Halo of a block, fraction of its side")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.49));
  sub.add_option("--block-max-segments", options.block_max_segments,
                 "Split a block with more lines than this into 8, recursively (0 = never)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

nlohmann::json DetectionOptionsJson(const PlaneDetectionOptions& options) {
  nlohmann::json j = {{"epsilon", options.epsilon},
                      {"iterations", options.iterations},
                      {"max_planes", options.max_planes},
                      {"min_support", options.min_support},
                      {"collinear_tolerance", options.collinear_tolerance},
                      {"block_size", options.block_size},
                      {"block_halo", options.block_halo},
                      {"block_max_segments", options.block_max_segments},
                      {"seed", options.seed}};
  j["relative_epsilon"] =
      options.relative_epsilon ? nlohmann::json(*options.relative_epsilon) : nlohmann::json();
  return j;
}

}  // namespace linesurf::cli
