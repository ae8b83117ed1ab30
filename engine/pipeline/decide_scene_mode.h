#pragma once
/// @file decide_scene_mode.h
/// @brief The automatic choice between an exterior scene (an object seen from outside: cells on
/// the box empty) and an interior scene (a room seen from inside: cells on the box full).
///
/// Rule (docs/design/reconstruction.md): a viewpoint is enclosed when all but at most `open_rays` of 14
/// rays from it (the 6 axis directions and the 8 diagonals) meet a plane at a point that the
/// plane's inlier segments surround: in the plane, each of 8 directions from that point crosses an
/// inlier (inliers lengthened by `gap_bridge` of their length at each end, which bridges the gaps
/// between the pieces of one cut line). The scene is interior when more than half of the
/// observing viewpoints examined (all, or an even sample of max_viewpoints) are enclosed. A room
/// has walls, floor and ceiling all around its cameras; a house seen from a ring of cameras, or a
/// street seen from street level, leaves open directions (away from the house, or the sky).
///
/// Why surround and not the inliers' bounding box: a plane whose inliers are spread over a
/// whole city (the floor bands of every building at one height) has a bounding box that covers
/// the streets, so every street viewpoint would look enclosed by it (763 of the 1,100
/// viewpoints of a synthetic city did).

#include "engine/core/run_context.h"
#include "engine/core/scene.h"

#include <cstddef>
#include <string>

namespace linesurf::pipeline {

struct SceneModeOptions {
  /// Each inlier counts as lengthened by this fraction of its length at both ends ([0, 0.5]).
  /// 0.15: the synthetic generator trims pieces by up to 10 % per end; real lines have gaps too.
  double gap_bridge = 0.15;
  /// A viewpoint is still enclosed when this many of its 14 rays meet no surrounded plane
  /// ([0, 14]). 3: a plane that lost the segments of one of its edges to other planes leaves a
  /// few rays open from inside a room (synth room at 2 cm, seed 3: 3 of 14 viewpoints with every
  /// ray closed, 12 with at most 3 open), while outside a building or in a street the sky and
  /// the directions away from the walls leave at least 6 open (docs/design/reconstruction.md).
  int open_rays = 3;
  /// At most this many observing viewpoints are examined, evenly spaced in index order (>= 1):
  /// the decision is a majority, which a sample of 1,000 estimates within a few points (well
  /// inside the weak band), while each viewpoint costs rays against planes whose inliers grow
  /// with the scene (city-1000, 6,402 viewpoints: 16 s of 208 with every viewpoint).
  std::size_t max_viewpoints = 1000;
  /// The decision is weak (reported in warnings) when the enclosed share of the observing
  /// viewpoints lies in [weak_low, weak_high].
  double weak_low = 0.25;
  double weak_high = 0.75;
};

struct SceneModeDecision {
  bool interior = false;
  /// The enclosed share is close to one half (see SceneModeOptions): the evidence hardly
  /// prefers one mode; the caller should warn and suggest choosing the mode explicitly.
  bool weak = false;
  std::size_t enclosed_viewpoints = 0;
  /// The observing viewpoints examined: all of them, or a sample of max_viewpoints.
  std::size_t observing_viewpoints = 0;
  /// How many viewpoints observe a segment (observing_viewpoints when there was no sample).
  std::size_t sampled_from = 0;
  /// One sentence, e.g. "auto: 12 of 12 viewpoints enclosed by planes (at most 3 of 14 rays
  /// open) -> interior".
  std::string reason;
};

/// Decides from the planes, memberships and viewpoints of `scene` (scenes without planes or
/// memberships are exterior). Deterministic, any thread count (exact counts); viewpoints in
/// parallel on ctx.num_threads. Each ray tests only the planes whose hit box it meets (a BoxBvh
/// over the planes' outlines: O(log planes) per ray where it was O(planes)), plus, per hit
/// inside a plane's inlier box, O(its inliers).
[[nodiscard]] SceneModeDecision DecideSceneMode(const Scene& scene,
                                                const SceneModeOptions& options = {},
                                                const RunContext& ctx = {});

}  // namespace linesurf::pipeline
