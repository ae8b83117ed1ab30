#pragma once
/// @file plane_arrangement.h
/// @brief The exact cell complex of a box split by planes (partition/arrangement), behind plain
/// types for `linesurf arrange`: counts, the validator of every invariant and the cells as PLY.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "linesurf/error.h"
#include "linesurf/run_control.h"
#include "linesurf/types.h"

namespace linesurf::arrange {

struct ArrangementCounts {
  std::size_t cells = 0;
  std::size_t facets = 0;
  std::size_t edges = 0;
  std::size_t vertices = 0;
  std::size_t planes_input = 0;
  std::size_t planes_used = 0;
  std::size_t planes_skipped_outside = 0;   ///< miss the box
  std::size_t planes_skipped_touching = 0;  ///< only touch it
  std::size_t planes_duplicate = 0;         ///< same or opposite orientation as one before
  std::size_t planes_invalid = 0;
  std::size_t exact_fallbacks = 0;  ///< predicates decided in exact arithmetic
  double seconds = 0.0;
};

/// True when both corners are finite and min < max on every axis (what Build accepts).
[[nodiscard]] bool IsBox(const Vector3& box_min, const Vector3& box_max) noexcept;

/// kInvalidOptions unless `shrink` (of WriteCellsPly) is in (0, 1].
[[nodiscard]] Status ValidateCellsShrink(double shrink) noexcept;

class PlaneArrangement {
 public:
  /// @brief Splits the box [box_min, box_max] by `planes` (both in world coordinates; the
  /// complex is built in a frame centred on the box). Serial; `control` can cancel between
  /// planes. Errors: kInvalidInput (an empty box), kCancelled.
  [[nodiscard]] static Expected<PlaneArrangement> Build(const Vector3& box_min,
                                                        const Vector3& box_max,
                                                        std::span<const Plane> planes,
                                                        const RunControl& control) noexcept;

  [[nodiscard]] const ArrangementCounts& Counts() const noexcept;
  /// Planes skipped, and why.
  [[nodiscard]] const std::vector<std::string>& Warnings() const noexcept;
  /// Checks every invariant of the complex (slow); the error says which one fails.
  [[nodiscard]] Status Validate() const noexcept;
  /// The cells, each shrunk by `shrink` towards its centroid, as binary PLY in world
  /// coordinates (a `cell` id and a colour per face).
  [[nodiscard]] Status WriteCellsPly(const std::filesystem::path& path,
                                     double shrink) const noexcept;

  PlaneArrangement(PlaneArrangement&&) noexcept;
  PlaneArrangement& operator=(PlaneArrangement&&) noexcept;
  ~PlaneArrangement();

 private:
  struct Impl;
  explicit PlaneArrangement(std::unique_ptr<Impl> impl) noexcept;
  std::unique_ptr<Impl> impl_;
};

}  // namespace linesurf::arrange
