#include "engine/detect/plane_fusion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <span>
#include <tuple>

#include "engine/detect/segment_geometry.h"

namespace linesurf::detect {
namespace {

struct FusionNode {
  SupportedPlane data;
  Box3 box;  ///< of the inliers' endpoints
  std::size_t key = 0;  ///< output position: the smallest input index among its parents
  bool alive = true;
};

Box3 InlierBox(std::span<const Segment3> segments, const std::vector<SegmentId>& inliers) {
  Box3 box;
  for (const SegmentId s : inliers) {
    box.Extend(segments[s.index()].p1);
    box.Extend(segments[s.index()].p2);
  }
  return box;
}

/// Largest per-axis gap between two boxes (0 when they overlap).
double BoxGap(const Box3& a, const Box3& b) {
  return (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0).maxCoeff();
}

double AngleBetween(const Plane3& a, const Plane3& b) {
  return std::acos(std::min(1.0, std::abs(a.normal.dot(b.normal))));
}

std::vector<SegmentId> UnionOf(const std::vector<SegmentId>& a, const std::vector<SegmentId>& b) {
  std::vector<SegmentId> out;
  out.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

/// Whether some point of the inliers' box lies within `tolerance` of `plane`, with a relative
/// slack for rounding. Both segment distances (mean and max of the endpoints') are at least the
/// smallest distance over the box, so no inlier of a box that misses the slab is within it.
bool BoxMeetsSlab(const Box3& box, const Plane3& plane, double tolerance) {
  const double slack =
      1e-9 * (tolerance + box.Extent().norm() + box.Center().norm() + plane.point.norm());
  return BoxMeetsSlab(box.Center(), 0.5 * box.Extent(), plane, tolerance + slack);
}

/// The segments of the two supports that may lie within `tolerance` of both planes, held in
/// `storage` when it takes a union: the inliers of a node whose box misses the other plane's
/// slab cannot (the ground against a roof: its support of the whole city is skipped without a
/// look at its segments).
std::span<const SegmentId> SharedCandidates(const FusionNode& a, const FusionNode& b,
                                            double tolerance, std::vector<SegmentId>& storage) {
  const bool a_near_b = BoxMeetsSlab(a.box, b.data.plane, tolerance);
  const bool b_near_a = BoxMeetsSlab(b.box, a.data.plane, tolerance);
  if (a_near_b && b_near_a) {
    storage = UnionOf(a.data.inliers, b.data.inliers);
    return storage;
  }
  if (a_near_b) return a.data.inliers;
  if (b_near_a) return b.data.inliers;
  return {};
}

/// Angle of a mergeable pair, or a negative value when the pair does not qualify.
double PairAngle(std::span<const Segment3> segments, const FusionParameters& params,
                 const FusionNode& node_a, const FusionNode& node_b) {
  const SupportedPlane& a = node_a.data;
  const SupportedPlane& b = node_b.data;
  const double angle = AngleBetween(a.plane, b.plane);
  if (angle >= params.max_angle_rad) return -1.0;
  if (BoxGap(node_a.box, node_b.box) > params.max_gap) return -1.0;
  const std::size_t smaller = std::min(a.inliers.size(), b.inliers.size());
  const double needed = params.min_shared_fraction * static_cast<double>(smaller);
  std::size_t shared = 0;
  std::vector<SegmentId> storage;
  for (const SegmentId s : SharedCandidates(node_a, node_b, params.epsilon, storage)) {
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
    const Box3 box = InlierBox(segments, planes[i].inliers);
    nodes.push_back({std::move(planes[i]), box, i, true});
  }
  // Pending pairs ordered by (angle, i, j): a total order, so the greedy pass is deterministic.
  std::set<std::tuple<double, std::size_t, std::size_t>> queue;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < nodes.size(); ++j) {
      const double angle = PairAngle(segments, params, nodes[i], nodes[j]);
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
    Box3 box = nodes[i].box;
    box.Extend(nodes[j].box.min);
    box.Extend(nodes[j].box.max);
    nodes.push_back({SupportedPlane{plane, std::move(merged)}, box, key, true});
    ++merges;
    const std::size_t fresh = nodes.size() - 1;
    for (std::size_t k = 0; k < fresh; ++k) {
      if (!nodes[k].alive) continue;
      const double a = PairAngle(segments, params, nodes[k], nodes[fresh]);
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

std::int64_t LimitMemberships(std::size_t num_segments, std::int32_t min_support,
                              std::vector<SupportedPlane>& planes) {
  std::vector<std::size_t> order(planes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return planes[a].inliers.size() > planes[b].inliers.size();
  });
  std::vector<std::uint8_t> count(num_segments, 0);
  std::int64_t removed = 0;
  for (const std::size_t p : order) {
    std::vector<SegmentId>& inliers = planes[p].inliers;
    const auto kept = std::remove_if(inliers.begin(), inliers.end(),
                                     [&](SegmentId s) { return count[s.index()] >= 2; });
    removed += inliers.end() - kept;
    inliers.erase(kept, inliers.end());
    if (inliers.size() < static_cast<std::size_t>(min_support)) {
      removed += static_cast<std::int64_t>(inliers.size());
      inliers.clear();  // the plane goes: its segments stay free for the next planes
      continue;
    }
    for (const SegmentId s : inliers) ++count[s.index()];
  }
  std::erase_if(planes, [](const SupportedPlane& p) { return p.inliers.empty(); });
  return removed;
}

}  // namespace linesurf::detect
