#include "tools/cli/detection_options.h"

#include "tools/cli/option_checks.h"

namespace linesurf::cli {

void RegisterDetectionOptions(OptionRegistry& registry,
                              DetectionParameters& options,
                              const std::string& block_prefix) {
  registry
      .Add("epsilon",
           options.epsilon,
           "Inlier tolerance eps, scene units (unset: auto, estimated from the data)")
      ->check(Above(0.0));
  registry
      .Add("epsilon-over-noise",
           options.epsilon_over_noise,
           "eps auto: eps = this x the robust noise scale of the plane residuals")
      ->check(Between(1e-9, 20.0));
  registry.Add("relative-epsilon",
               options.relative_epsilon,
               "eps as a fraction of the scene diagonal (overrides --epsilon)");
  registry.Add("iterations", options.iterations, "Max candidate pairs per plane")
      ->check(Above(0.0));
  registry
      .Add("max-planes",
           options.max_planes,
           "Max number of planes (per block with --" + block_prefix + "block-size)")
      ->check(Above(0.0));
  registry.Add("min-support", options.min_support, "Min inlier segments per plane");
  registry
      .Add("support-gap",
           options.support_gap,
           "A plane whose support comes in pieces this many median line lengths apart that "
           "disagree about it keeps its largest piece (0 = off)")
      ->check(Between(0.0, 1000.0));
  registry
      .Add("collinear-tolerance",
           options.collinear_tolerance,
           "Segments on one line within this x eps are detected as one (0 = off)")
      ->check(Between(0.0, 0.5));
  registry
      .Add(block_prefix + "block-size",
           options.block_size,
           "Per-block detection: cube side, scene units (0 = whole scene at once" +
               std::string(block_prefix.empty() ? ")" : "; automatic with --engine blocks)"))
      ->check(AtLeast(0.0));
  registry
      .Add(block_prefix + "block-halo",
           options.block_halo,
           "Halo of a detection block, fraction of its side")
      ->check(Between(0.0, 0.49));
  registry
      .Add(block_prefix + "block-max-segments",
           options.block_max_segments,
           "Split a block with more lines than this into 8, recursively (0 = never)")
      ->check(AtLeast(0.0));
}

}  // namespace linesurf::cli

namespace linesurf::cli {

nlohmann::json EpsilonJson(const EpsilonEstimate& e) {
  return {{"epsilon", e.epsilon},
          {"source", e.source},
          {"noise_scale", e.noise_scale},
          {"initial_epsilon", e.initial_epsilon},
          {"rounds", e.rounds},
          {"residuals", e.residuals}};
}

}  // namespace linesurf::cli
