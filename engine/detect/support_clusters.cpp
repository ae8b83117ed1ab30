#include "engine/detect/support_clusters.h"

#include "engine/core/disjoint_sets.h"
#include "engine/detect/segment_geometry.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace linesurf::detect {

double SegmentSegmentDistance(const Segment3& a, const Segment3& b) {
  // Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9).
  const Vec3 d1 = a.p2 - a.p1;
  const Vec3 d2 = b.p2 - b.p1;
  const Vec3 r = a.p1 - b.p1;
  const double aa = d1.squaredNorm();
  const double ee = d2.squaredNorm();
  const double f = d2.dot(r);
  double s = 0.0;
  double t = 0.0;
  if (aa <= 0.0 && ee <= 0.0) return r.norm();
  if (aa <= 0.0) {
    t = std::clamp(f / ee, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (ee <= 0.0) {
      s = std::clamp(-c / aa, 0.0, 1.0);
    } else {
      const double bb = d1.dot(d2);
      const double denom = aa * ee - bb * bb;
      s = denom > 0.0 ? std::clamp((bb * f - c * ee) / denom, 0.0, 1.0) : 0.0;
      t = (bb * s + f) / ee;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / aa, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((bb - c) / aa, 0.0, 1.0);
      }
    }
  }
  return ((a.p1 + s * d1) - (b.p1 + t * d2)).norm();
}

std::vector<std::vector<SegmentId>> SupportClusters(std::span<const Segment3> segments,
                                                    std::span<const SegmentId> inliers,
                                                    double gap) {
  const std::size_t n = inliers.size();
  std::vector<Box3> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    boxes[i].Extend(segments[inliers[i].index()].p1);
    boxes[i].Extend(segments[inliers[i].index()].p2);
  }
  // Sweep along x: only segments whose x-intervals come within `gap` can be linked.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return boxes[i].min.x() != boxes[j].min.x() ? boxes[i].min.x() < boxes[j].min.x() : i < j;
  });
  DisjointSets sets(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t l = k + 1; l < n && boxes[order[l]].min.x() <= boxes[i].max.x() + gap; ++l) {
      const std::size_t j = order[l];
      if (sets.Find(i) == sets.Find(j)) continue;
      const double box_gap =
          (boxes[i].min - boxes[j].max).cwiseMax(boxes[j].min - boxes[i].max).maxCoeff();
      if (box_gap > gap) continue;
      if (SegmentSegmentDistance(segments[inliers[i].index()], segments[inliers[j].index()]) <=
          gap) {
        sets.Union(i, j);
      }
    }
  }
  std::vector<std::vector<SegmentId>> pieces;
  std::vector<std::size_t> piece_of_root(n, n);
  for (std::size_t i = 0; i < n; ++i) {  // inliers are sorted, so every piece is too
    const std::size_t root = sets.Find(i);
    if (piece_of_root[root] == n) {
      piece_of_root[root] = pieces.size();
      pieces.emplace_back();
    }
    pieces[piece_of_root[root]].push_back(inliers[i]);
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const auto& x, const auto& y) {
    return x.size() > y.size();
  });
  return pieces;
}

bool PiecesDisagree(std::span<const Segment3> segments,
                    const std::vector<std::vector<SegmentId>>& pieces,
                    const Plane3& plane,
                    std::size_t min_lines,
                    double min_width,
                    double tolerance) {
  for (const std::vector<SegmentId>& piece : pieces) {
    if (piece.size() < min_lines) continue;
    double width = 0.0;
    const Plane3 own = FitPlane(segments, piece, plane.normal, &width);
    if (width < min_width) continue;  // nearly collinear: its own tilt is noise
    for (const SegmentId s : piece) {
      for (const Vec3& p : {segments[s.index()].p1, segments[s.index()].p2}) {
        if (std::abs(plane.SignedDistance(p) - own.SignedDistance(p)) > tolerance) return true;
      }
    }
  }
  return false;
}

}  // namespace linesurf::detect
