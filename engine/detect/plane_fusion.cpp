#include "engine/detect/plane_fusion.h"

#include "engine/core/box_bvh.h"
#include "engine/core/endpoint_box.h"
#include "engine/detect/segment_bvh.h"
#include "engine/detect/segment_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <span>
#include <tuple>
#include <unordered_set>

namespace linesurf::detect {
namespace {

/// Supports larger than this are searched through the slab indexes of their pieces rather than
/// walked: a merged ground of the whole city is met again by every piece of ground around it.
constexpr std::size_t kIndexedSupport = 256;

/// Slack on an angle between two planes computed with acos, far above its rounding (about 1e-8
/// where the planes are nearly parallel).
constexpr double kAngleSlack = 1e-6;

/// The support of one input plane, with a hierarchy for slab queries built on first use. A merged
/// plane's support is the union of its input planes' (merges take unions), so it is searched
/// through their pieces and no index is rebuilt when the ground grows by one more piece.
class SupportPiece {
 public:
  explicit SupportPiece(std::vector<SegmentId> inliers) : inliers_(std::move(inliers)) {}

  /// Calls fn(s) for the inliers s that can lie in the slab |n.(x - o)| <= half_thickness (among
  /// others: SegmentBvh::ForEachInSlab) until it returns true; returns whether it did.
  template <typename Fn>
  bool AnyInSlab(std::span<const Segment3> segments,
                 const Plane3& plane,
                 double half_thickness,
                 Fn&& fn) {
    if (!bvh_) {
      std::vector<Segment3> own;
      own.reserve(inliers_.size());
      for (const SegmentId s : inliers_) own.push_back(segments[s.index()]);
      bvh_ = std::make_unique<SegmentBvh>(own);
    }
    return bvh_->AnyInSlab(
        plane, half_thickness, [&](SegmentId local) { return fn(inliers_[local.index()]); });
  }

 private:
  std::vector<SegmentId> inliers_;
  std::unique_ptr<SegmentBvh> bvh_;
};

struct FusionNode {
  SupportedPlane data;
  Box3 box;             ///< of the inliers' endpoints
  std::size_t key = 0;  ///< output position: the smallest input index among its parents
  bool alive = true;
  std::vector<std::shared_ptr<SupportPiece>> pieces;  ///< their union is data.inliers
};

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

/// `tolerance` plus a slack for rounding, relative to it, to the size and place of `box` and to
/// `place` (the norm of another point the test involves).
double WithRoundingSlack(double tolerance, const Box3& box, double place = 0.0) {
  return tolerance + 1e-9 * (tolerance + box.Extent().norm() + box.Center().norm() + place);
}

/// `tolerance` plus the slack, for a test of `box` against the slab of `plane`.
double SlabTolerance(const Box3& box, const Plane3& plane, double tolerance) {
  return WithRoundingSlack(tolerance, box, plane.point.norm());
}

/// Whether some point of the inliers' box lies within `tolerance` of `plane` (with the slack).
/// Both segment distances (mean and max of the endpoints') are at least the smallest distance
/// over the segment's box, so no inlier of a box that misses the slab is within it.
bool BoxMeetsSlab(const Box3& box, const Plane3& plane, double tolerance) {
  return BoxMeetsSlab(
      box.Center(), 0.5 * box.Extent(), plane, SlabTolerance(box, plane, tolerance));
}

/// Whether at least `needed` (and at least one) segments of the two supports lie within
/// params.epsilon of both planes, each segment counted once. The smaller support is walked; the
/// larger is walked too when small, and otherwise searched through its pieces' indexes for the
/// segments that can lie within epsilon of the smaller's plane (the merged ground of a city
/// against one more piece of ground looks at the band where the two planes meet, not at the
/// whole ground). A support whose box misses the other plane's slab cannot count and is
/// skipped. The walks stop as soon as the answer is known.
bool SharesEnough(std::span<const Segment3> segments,
                  const FusionParameters& params,
                  const FusionNode& node_a,
                  const FusionNode& node_b,
                  double needed) {
  const bool a_is_smaller = node_a.data.inliers.size() <= node_b.data.inliers.size();
  const FusionNode& small = a_is_smaller ? node_a : node_b;
  const FusionNode& large = a_is_smaller ? node_b : node_a;
  const auto near_both = [&](SegmentId s) {
    const Segment3& seg = segments[s.index()];
    return SegmentPlaneDistance(seg, small.data.plane, params.distance) <= params.epsilon &&
           SegmentPlaneDistance(seg, large.data.plane, params.distance) <= params.epsilon;
  };
  const double goal = std::max(needed, 1.0);
  double shared = 0.0;
  const bool small_counts = BoxMeetsSlab(small.box, large.data.plane, params.epsilon);
  if (small_counts) {
    for (const SegmentId s : small.data.inliers) {
      if (near_both(s) && ++shared >= goal) return true;
    }
  }
  if (!BoxMeetsSlab(large.box, small.data.plane, params.epsilon)) return false;
  // Whether a segment of the larger support reaches the goal; a segment of both supports was
  // counted with the smaller one.
  const auto counts_to_goal = [&](SegmentId s) {
    if (small_counts &&
        std::binary_search(small.data.inliers.begin(), small.data.inliers.end(), s)) {
      return false;
    }
    return near_both(s) && ++shared >= goal;
  };
  if (large.data.inliers.size() <= kIndexedSupport) {
    return std::any_of(large.data.inliers.begin(), large.data.inliers.end(), counts_to_goal);
  }
  // The pieces may share segments: each counts once, whichever piece meets it first (the count
  // of distinct segments near both planes does not depend on the order).
  const double half_thickness = SlabTolerance(large.box, small.data.plane, params.epsilon);
  std::unordered_set<std::uint32_t> met;
  const bool several = large.pieces.size() > 1;
  return std::any_of(large.pieces.begin(), large.pieces.end(), [&](const auto& piece) {
    return piece->AnyInSlab(segments, small.data.plane, half_thickness, [&](SegmentId s) {
      if (several && !met.insert(s.index()).second) return false;
      return counts_to_goal(s);
    });
  });
}

/// Angle of a mergeable pair, or a negative value when the pair does not qualify.
double PairAngle(std::span<const Segment3> segments,
                 const FusionParameters& params,
                 const FusionNode& node_a,
                 const FusionNode& node_b) {
  if (BoxGap(node_a.box, node_b.box) > params.max_gap) return -1.0;
  const double angle = AngleBetween(node_a.data.plane, node_b.data.plane);
  if (angle >= params.max_angle_rad) return -1.0;
  const std::size_t smaller = std::min(node_a.data.inliers.size(), node_b.data.inliers.size());
  const double needed = params.min_shared_fraction * static_cast<double>(smaller);
  return SharesEnough(segments, params, node_a, node_b, needed) ? angle : -1.0;
}

/// The alive nodes' boxes in one hierarchy per class of normal (the axis of its largest
/// component), so that a query skips the classes no normal within max_angle of its own can belong
/// to, and the nodes added since the hierarchies were built, in a list with their boxes and
/// classes. Normals are unit (RANSAC and FitPlane normalise them). A node that dies stays where
/// it is until the deaths and additions since the last build outnumber a quarter of what the
/// hierarchies hold (and 64); then they are rebuilt from the alive nodes. Before, every merge
/// walked every merged plane so far, and a merged plane's query met again every piece it had
/// swallowed (a street's facade or a city's ground grows piece by piece).
class NearNodeIndex {
 public:
  explicit NearNodeIndex(double max_angle) : reach_(2.0 * (max_angle + kAngleSlack)) {}

  /// Indexes the alive nodes, and forgets the added and dead ones.
  void Rebuild(const std::vector<FusionNode>& nodes) {
    std::array<std::vector<Box3>, 3> boxes;
    for (auto& members : members_) members.clear();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (!nodes[i].alive) continue;
      const int c = ClassOf(nodes[i].data.plane.normal);
      boxes[c].push_back(nodes[i].box);
      members_[c].push_back(i);
    }
    indexed_ = 0;
    for (int c = 0; c < 3; ++c) {
      bvh_[c] = std::make_unique<BoxBvh>(boxes[c]);
      indexed_ += members_[c].size();
    }
    added_.clear();
    stale_ = 0;
  }

  /// Node `i` joins the list (it is found from the next query on).
  void Add(std::size_t i, const FusionNode& node) {
    added_.push_back({i, node.box, ClassOf(node.data.plane.normal)});
    ++stale_;
  }

  /// One node died (indexed or added).
  void Retire() { ++stale_; }

  /// Whether a rebuild now pays.
  [[nodiscard]] bool Stale() const {
    return stale_ > std::max(kMinStale, indexed_ / kStaleShareInverse);
  }

  /// Calls fn(i) for every node i, dead ones included, whose box overlaps `box` (boundaries
  /// included) and whose normal may lie within max_angle of `normal` (unit): the indexed ones,
  /// class by class, then the added ones.
  template <typename Fn>
  void ForEachNear(const Box3& box, const Vec3& normal, Fn&& fn) const {
    const Vec3 magnitude = normal.cwiseAbs();
    // A unit normal n within angle a of +-normal m differs from it by at most a in every
    // component; if n's largest component is c, then |m_c| >= |n_c| - a >= |n_k| - a >= |m_k| - 2a
    // for every axis k.
    const auto class_may_hold = [&](int c) {
      return magnitude[c] >= magnitude.maxCoeff() - reach_;
    };
    for (int c = 0; c < 3; ++c) {
      if (!class_may_hold(c)) continue;
      bvh_[c]->AnyOverlapping(box, [&](std::uint32_t k) {
        fn(members_[c][k]);
        return false;
      });
    }
    for (const Added& a : added_) {
      if (class_may_hold(a.cls) && box.Overlaps(a.box)) {
        fn(a.node);
      }
    }
  }

 private:
  /// Rebuild when the deaths and additions since the last build number more than a quarter of
  /// the indexed nodes and more than 64 (a rebuild costs n log n; a query walks the added list).
  static constexpr std::size_t kMinStale = 64;
  static constexpr std::size_t kStaleShareInverse = 4;

  struct Added {
    std::size_t node;
    Box3 box;
    int cls;  ///< class of its normal
  };

  static int ClassOf(const Vec3& normal) {
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    return axis;
  }

  double reach_;  ///< how far below the largest component a class's may lie: 2 (max_angle + slack)
  std::array<std::vector<std::size_t>, 3> members_;
  std::array<std::unique_ptr<BoxBvh>, 3> bvh_;
  std::vector<Added> added_;
  std::size_t indexed_ = 0;
  std::size_t stale_ = 0;
};

}  // namespace

int FusePlanes(std::span<const Segment3> segments,
               const FusionParameters& params,
               std::vector<SupportedPlane>& planes) {
  std::vector<FusionNode> nodes;
  nodes.reserve(2 * planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Box3 box = EndpointBox(segments, planes[i].inliers);
    auto piece = std::make_shared<SupportPiece>(planes[i].inliers);
    nodes.push_back({std::move(planes[i]), box, i, true, {std::move(piece)}});
  }
  // Pending pairs, smallest (angle, i, j) first: a total order, and no pair is pushed twice (a
  // fresh node's pairs are new), so the greedy pass is deterministic whatever order the pairs are
  // found in.
  using Pair = std::tuple<double, std::size_t, std::size_t>;
  std::priority_queue<Pair, std::vector<Pair>, std::greater<>> queue;
  // The planes whose boxes come within max_gap of a box and whose normals may lie within
  // max_angle of a normal: the only partners PairAngle can accept among them, found without
  // pairing every plane with every other (the walls of a street are not asked about its roofs).
  NearNodeIndex near_nodes(params.max_angle_rad);
  near_nodes.Rebuild(nodes);
  const auto for_each_node_near = [&](const FusionNode& node, auto&& fn) {
    Box3 reach = node.box;
    // A box within max_gap of `box` by BoxGap overlaps `box` grown by this on every side.
    const double gap = WithRoundingSlack(params.max_gap, node.box);
    reach.min.array() -= gap;
    reach.max.array() += gap;
    near_nodes.ForEachNear(reach, node.data.plane.normal, fn);
  };
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for_each_node_near(nodes[i], [&](std::size_t j) {
      if (j <= i) return;
      const double angle = PairAngle(segments, params, nodes[i], nodes[j]);
      if (angle >= 0.0) queue.emplace(angle, i, j);
    });
  }
  int merges = 0;
  while (!queue.empty()) {
    const auto [angle, i, j] = queue.top();
    queue.pop();
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
    near_nodes.Retire();
    near_nodes.Retire();
    std::vector<std::shared_ptr<SupportPiece>> pieces = std::move(nodes[i].pieces);
    pieces.insert(pieces.end(), nodes[j].pieces.begin(), nodes[j].pieces.end());
    nodes[j].pieces.clear();
    const std::size_t key = std::min(nodes[i].key, nodes[j].key);
    Box3 box = nodes[i].box;
    box.Extend(nodes[j].box.min);
    box.Extend(nodes[j].box.max);
    nodes.push_back({SupportedPlane{plane, std::move(merged)}, box, key, true, std::move(pieces)});
    ++merges;
    const std::size_t fresh = nodes.size() - 1;
    const auto pair_with_fresh = [&](std::size_t k) {
      if (!nodes[k].alive) return;
      const double a = PairAngle(segments, params, nodes[k], nodes[fresh]);
      if (a >= 0.0) queue.emplace(a, k, fresh);
    };
    for_each_node_near(nodes[fresh], pair_with_fresh);
    near_nodes.Add(fresh, nodes[fresh]);
    if (near_nodes.Stale()) near_nodes.Rebuild(nodes);
  }
  std::vector<FusionNode*> alive;
  for (FusionNode& node : nodes) {
    if (node.alive) alive.push_back(&node);
  }
  std::sort(alive.begin(), alive.end(), [](const FusionNode* a, const FusionNode* b) {
    return a->key < b->key;
  });
  planes.clear();
  for (FusionNode* node : alive) planes.push_back(std::move(node->data));
  return merges;
}

std::int64_t LimitMemberships(std::size_t num_segments,
                              std::int32_t min_support,
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
    const auto kept = std::remove_if(
        inliers.begin(), inliers.end(), [&](SegmentId s) { return count[s.index()] >= 2; });
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
