#include "engine/detect/plane_fusion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include "engine/detect/segment_geometry.h"

namespace linesurf::detect {
namespace {

struct FusionNode {
  SupportedPlane data;
  std::size_t key = 0;  ///< output position: the smallest input index among its parents
  bool alive = true;
};

double AngleBetween(const Plane3& a, const Plane3& b) {
  return std::acos(std::min(1.0, std::abs(a.normal.dot(b.normal))));
}

std::vector<SegmentId> UnionOf(const std::vector<SegmentId>& a, const std::vector<SegmentId>& b) {
  std::vector<SegmentId> out;
  out.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

/// Angle of a mergeable pair, or a negative value when the pair does not qualify.
double PairAngle(std::span<const Segment3> segments, const FusionParameters& params,
                 const SupportedPlane& a, const SupportedPlane& b) {
  const double angle = AngleBetween(a.plane, b.plane);
  if (angle >= params.max_angle_rad) return -1.0;
  const std::size_t smaller = std::min(a.inliers.size(), b.inliers.size());
  const double needed = params.min_shared_fraction * static_cast<double>(smaller);
  std::size_t shared = 0;
  for (const SegmentId s : UnionOf(a.inliers, b.inliers)) {
    const Segment3& seg = segments[s.index()];
    if (SegmentPlaneDistance(seg, a.plane, params.distance) <= params.epsilon &&
        SegmentPlaneDistance(seg, b.plane, params.distance) <= params.epsilon) {
      ++shared;
    }
  }
  return static_cast<double>(shared) >= needed && shared > 0 ? angle : -1.0;
}

}  // namespace

int FusePlanes(std::span<const Segment3> segments, const FusionParameters& params,
               std::vector<SupportedPlane>& planes) {
  std::vector<FusionNode> nodes;
  nodes.reserve(2 * planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) {
    nodes.push_back({std::move(planes[i]), i, true});
  }
  // Pending pairs ordered by (angle, i, j): a total order, so the greedy pass is deterministic.
  std::set<std::tuple<double, std::size_t, std::size_t>> queue;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < nodes.size(); ++j) {
      const double angle = PairAngle(segments, params, nodes[i].data, nodes[j].data);
      if (angle >= 0.0) queue.emplace(angle, i, j);
    }
  }
  int merges = 0;
  while (!queue.empty()) {
    const auto [angle, i, j] = *queue.begin();
    queue.erase(queue.begin());
    if (!nodes[i].alive || !nodes[j].alive) continue;
    std::vector<SegmentId> merged = UnionOf(nodes[i].data.inliers, nodes[j].data.inliers);
    const Plane3 plane = FitPlane(segments, merged, nodes[i].data.plane.normal);
    const bool thin = std::all_of(merged.begin(), merged.end(), [&](SegmentId s) {
      return SegmentPlaneDistance(segments[s.index()], plane, params.distance) <=
             params.epsilon_fusion;
    });
    if (!thin) continue;
    nodes[i].alive = false;
    nodes[j].alive = false;
    const std::size_t key = std::min(nodes[i].key, nodes[j].key);
    nodes.push_back({SupportedPlane{plane, std::move(merged)}, key, true});
    ++merges;
    const std::size_t fresh = nodes.size() - 1;
    for (std::size_t k = 0; k < fresh; ++k) {
      if (!nodes[k].alive) continue;
      const double a = PairAngle(segments, params, nodes[k].data, nodes[fresh].data);
      if (a >= 0.0) queue.emplace(a, k, fresh);
    }
  }
  std::vector<FusionNode*> alive;
  for (FusionNode& node : nodes) {
    if (node.alive) alive.push_back(&node);
  }
  std::sort(alive.begin(), alive.end(),
            [](const FusionNode* a, const FusionNode* b) { return a->key < b->key; });
  planes.clear();
  for (FusionNode* node : alive) planes.push_back(std::move(node->data));
  return merges;
}

}  // namespace linesurf::detect
