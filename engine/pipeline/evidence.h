#pragma once
/// @file evidence.h
/// @brief The evidence of the line segments on the cells: the energy terms of the paper as a
/// solver::EnergyInput, their options, scale rules and result (ComputeBlockEvidence,
/// block_evidence.h, computes them; see docs/design/reconstruction.md).
///
/// Every segment contributes per unit of its length, divided by the scale sigma. The segment is
/// integrated with K midpoint samples (K = ceil(samples_per_sigma * length / sigma), clamped to
/// [1, max_samples_per_segment]); each sample stands for length / K.
///  - textural (1 plane P, segment projected onto P): for each viewpoint v, the cell just behind
///    the sample (across P, away from v) pays w_tex * length / (K sigma) if empty;
///  - structural (2 planes, segment projected onto P1 ∩ P2): the four quadrant cells around the
///    crease except the one facing v form one group paying w_str * length / (K sigma) *
///    max(0, 1 - sum x) (identical groups are merged);
///  - crease (same sample and view; CreaseWeight: interior scenes only by default): with A, B the
///    cells across P1 and across P2 from the one facing v and D the cell across both, the flat
///    labellings through the crease pay w_crease * length / (K sigma views) * x_D |x_A - x_B|,
///    written as parity groups with constant -1 (segment_evidence.h, CreaseEntry);
///  - visibility: the sight ray from v to the sample (ending in the cell in front of the segment,
///    so facets the segment lies on are exempt) adds w_vis * length / (K sigma) to every facet it
///    crosses: a pairwise |x_a - x_b| term per facet. Segments without planes count here too;
///  - viewpoint prior: the cell holding v pays w_prior per observation if full;
///  - edge / corner regularisation (Boulch et al. 2014): for every interior edge a parity group
///    over its cells, weight w_edge * length / sigma; for every interior vertex a parity group over
///    the cells around it, weight w_corner;
///  - area (default 0): w_area * area / sigma^2 per interior facet, pairwise.
/// Sums are accumulated in fixed point (integer atomics), so the result is bit-identical for any
/// thread count and schedule.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/cell_complex.h"
#include "engine/core/run_context.h"
#include "engine/core/scene.h"
#include "linesurf/error.h"
#include "linesurf/options.h"
#include "solver/energy/energy_input.h"

namespace linesurf::pipeline {

struct EnergyOptions {
  /// The weights of the terms, the facade's own struct (linesurf/options.h, where their defaults
  /// and rationale are; their ranges are linesurf/option_schema.h's). An unset crease weight is
  /// CreaseWeight's default for the boundary mode.
  EnergyWeights weights;
  /// Scale sigma (scene units, > 0, at least 1e-9 of the box diagonal, and large enough that
  /// the total evidence weight x length / sigma x views stays below 2^31: ComputeBlockEvidence
  /// checks both). Unset: the median segment length of the scene (about 1 m on Andalusian,
  /// where the reference uses 1), so weights mean the same at any scene scale.
  std::optional<double> sigma;
  /// Samples per sigma of segment length ((0, 1000]); 4 resolves cells a quarter of a typical
  /// segment long.
  double samples_per_sigma = 4.0;
  /// Upper bound of K per segment ([1, 100000]).
  std::int32_t max_samples_per_segment = 64;
  /// A structural segment whose planes make less than this angle (degrees, [0, 45]) has an
  /// ill-defined crease: it is treated as textural on the nearer plane (counted in warnings).
  double min_crease_angle_deg = 5.0;
  /// Ablation: structural segments count as two textural segments (one per plane) instead of
  /// one structural group.
  bool structural_as_textural = false;

  /// Names the first out-of-range field; every weight must be in [0, 1e6].
  [[nodiscard]] Status Validate() const;
};

/// The bounds options alone cannot state (kInvalidOptions): sigma (given, or the default) at
/// least 1e-9 of the diagonal of `box`, and the total evidence (weight x length / sigma x views,
/// summed over the segments) within what the fixed-point accumulators hold (2^31), so no cost
/// wraps or overflows. ComputeBlockEvidence checks it; Reconstruct checks it before the complex.
[[nodiscard]] Status CheckEnergyScale(const Scene& scene,
                                      const Box3& box,
                                      const EnergyOptions& options);

/// Boundary condition on the cells touching the box.
enum class BoundaryMode {
  kExterior,  ///< cells on the box are empty (an object seen from outside)
  kInterior,  ///< cells on the box are full (a room seen from inside)
  kNone,      ///< no cell is fixed (tests)
};

/// The crease weight of an interior scene when none is given. In a scene seen from inside, most
/// structural segments are concave room corners, where the paper's term is satisfied by the floor
/// alone and an untextured wall between two rooms vanishes; 0.2 brings it back without costing
/// the other scenes more than seed noise (docs/user/results.md, "Crease term"). Exterior scenes get 0: facade lines
/// that only happen to be coplanar (sills, storey bands) give segments a second, false plane,
/// and a crease term there steps the walls at any weight that helps the interiors.
inline constexpr double kInteriorCreaseWeight = 0.2;

/// The crease weight used under `boundary`: the given one, else kInteriorCreaseWeight in an
/// interior scene and 0 otherwise.
[[nodiscard]] double CreaseWeight(const EnergyOptions& options, BoundaryMode boundary);

struct EvidenceStats {
  double sigma = 0.0;                               ///< the scale actually used
  double crease_weight = 0.0;                       ///< the crease weight actually used
  std::size_t segments_with_planes[3] = {0, 0, 0};  ///< segments on 0, 1, 2 planes
  std::size_t observations = 0;
  std::size_t samples = 0;                   ///< segment samples (all observations)
  std::size_t samples_outside_box = 0;       ///< skipped: the sample left the box
  std::size_t grazing_samples = 0;           ///< skipped: viewpoint in the segment's plane
  std::size_t walks = 0;                     ///< sight rays walked
  std::size_t facets_crossed = 0;            ///< facet crossings summed over all rays
  std::size_t parallel_creases = 0;          ///< structural segments treated as textural
  std::size_t viewpoints_outside_box = 0;    ///< viewpoints whose prior was skipped
  std::size_t fixed_cells = 0;
};

struct EvidenceResult {
  solver::EnergyInput energy;
  EvidenceStats stats;
  /// The cell holding each viewpoint (invalid outside the box).
  IdVector<ViewpointId, CellId> viewpoint_cells;
  std::vector<std::string> warnings;
};

/// The scale used when EnergyOptions::sigma is unset: the median segment length (1 when the
/// scene has no segment of positive length).
[[nodiscard]] double DefaultSigma(const Scene& scene);

}  // namespace linesurf::pipeline
