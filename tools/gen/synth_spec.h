#pragma once
/// @file synth_spec.h
/// @brief What a synthetic scene looks like (tools/gen/synthesize.h builds it): the family, the
/// seed and the artefacts of real line clouds to imitate. Plain types only, so the front ends
/// that describe a scene need no engine header.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "linesurf/error.h"

namespace linesurf::synth {

/// How endpoint noise is drawn.
enum class NoiseModel {
  kGaussian,     ///< each endpoint coordinate += N(0, noise_sigma^2)
  kUniformBall,  ///< each endpoint += a point uniform in the ball of radius noise_sigma (the
                 ///< paper's "perturbed by up to" robustness study)
  kDepth,        ///< triangulated (Line3D++-like): Gaussian, twice the standard deviation along
                 ///< the segment's mean viewing direction than across it, same total variance
                 ///< 3 noise_sigma^2 as kGaussian
};

/// Where outliers are drawn.
enum class OutlierModel {
  kUniform,  ///< in the family's box (cube: ball), uniform direction and length
  kNear,     ///< Line3D++-like false matches: a copy of a random visible piece moved along its
             ///< mean viewing direction by 0.1..1 m either way and turned by up to 15 degrees,
             ///< seen from that piece's views
};

/// What a synthetic scene looks like.
struct SynthSpec {
  /// "cube", "house", "lshape", "room", "floor" or "city".
  std::string family = "cube";
  /// Seed of every random choice.
  std::uint64_t seed = 0;
  /// city: number of buildings, 1..100000; 0 = 16. Ignored by the other families.
  int size = 0;
  /// Endpoint noise in metres (standard deviation, or ball radius for kUniformBall), 0..10.
  double noise_sigma = 0.0;
  /// Noise distribution; Gaussian by default.
  NoiseModel noise_model = NoiseModel::kGaussian;
  OutlierModel outlier_model = OutlierModel::kUniform;
  /// Fraction of the output segments that are outliers, in [0, 0.9]: round(f / (1 - f) * inliers).
  double outlier_fraction = 0.0;
  /// Exact number of outliers (0..1000000); overrides outlier_fraction when set.
  std::optional<int> outlier_count;
  /// Each true line is cut into 1..max_pieces pieces (1..16). Default: 1 for cube (its 12 edges
  /// exactly), 3 otherwise.
  std::optional<int> max_pieces;
  /// Each piece loses up to this fraction of its length at each end, uniformly drawn, in
  /// [0, 0.4]. Default: 0 for cube, 0.1 otherwise.
  std::optional<double> max_trim;
  /// Views listed per segment: the nearest viewpoints that see it, at most this many (1..64).
  int max_views = 8;
  /// Residual split, as the reference's converter makes Andalusian (docs/user/synthetic.md): every
  /// (segment, view) becomes its own sub-segment with that one view, the part of the segment's
  /// (noisy) line that one camera saw (each end loses a uniform 0..max_view_trim of its length)
  /// shrunk by 5 % (2.5 % at each end). Outliers are split too. Default false.
  bool residual_split = false;
  /// Residual split: largest share of a segment one camera misses at each end, [0, 0.45].
  double max_view_trim = 0.25;
  /// Output units per metre, in [1e-3, 1e3] (100: centimetres, 3.28084: feet): segments,
  /// viewpoints, planes, mesh and noise are scaled about the origin, as SfM picks its own unit.
  double scale = 1.0;
  /// Everything turned about the origin by rotation_degrees ([-360, 360]) around rotation_axis
  /// (finite, not zero; normalised), after the scale: an up axis other than z, as SfM picks its
  /// own frame. The data's up is then the rotated z axis (meta.json "up").
  std::array<double, 3> rotation_axis{0.0, 0.0, 1.0};
  double rotation_degrees = 0.0;
  /// Added to x and y of everything (segments, viewpoints, mesh, planes), after the scale and
  /// the rotation, in output units, to mimic georeferenced coordinates; |offset| <= 1e7. The
  /// scene's world_from_local stays identity.
  double offset = 0.0;

  /// Checks every field; names the first offending one.
  [[nodiscard]] Status Validate() const;
};

}  // namespace linesurf::synth
