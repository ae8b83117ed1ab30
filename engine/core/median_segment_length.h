#pragma once
// The typical length of a scene's segments: the unit-free scale of sigma (energy) and of eps_0
// (eps auto).

#include "engine/core/scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace linesurf {

/// Median length of the segments of finite positive length; 0 when there is none. O(n).
inline double MedianSegmentLength(const Scene& scene) {
  std::vector<double> lengths;
  lengths.reserve(scene.NumSegments());
  for (const Segment3& s : scene.segments) {
    const double l = s.Length();
    if (std::isfinite(l) && l > 0.0) lengths.push_back(l);
  }
  if (lengths.empty()) return 0.0;
  const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

}  // namespace linesurf
