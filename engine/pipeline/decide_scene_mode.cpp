#include "engine/pipeline/decide_scene_mode.h"

#include "engine/core/box_bvh.h"
#include "engine/core/parallel.h"

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <vector>

namespace linesurf::pipeline {
namespace {

/// Rays nearly parallel to a plane (|n.d| under this) do not hit it.
constexpr double kMinRayPlaneCosine = 1e-6;
/// In-plane directions that must each cross an inlier for a hit point to be surrounded.
constexpr std::size_t kInPlaneDirections = 8;
/// An in-plane direction and an inlier closer to parallel than this sine do not cross.
constexpr double kParallelSine = 1e-12;
/// Growth of a plane's hit box, relative to its coordinates: far above the rounding of a hit
/// point, so the box never drops a hit that the exact test would accept.
constexpr double kHitBoxMargin = 1e-7;
/// A plane with more inliers than this answers Surrounds through a hierarchy of its inliers'
/// boxes: a city's ground, walked inlier by inlier for each downward ray until every direction
/// was crossed, made the decision grow with the square of the city.
constexpr std::size_t kIndexedInliers = 64;
/// The hierarchy's boxes grow by this share of the plane's in-plane size, and its rays start that
/// far behind their point: a crossing nearly parallel to the direction (sine down to
/// kParallelSine) is computed up to about 7e-4 of that size away from where it is, and the exact
/// test may accept it there.
constexpr double kIndexReach = 2e-3;

using Vec2 = Eigen::Vector2d;

double Cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::array<Vec3, 14> RayDirections() {
  std::array<Vec3, 14> dirs;
  std::size_t k = 0;
  for (int a = 0; a < 3; ++a) {
    for (const double s : {1.0, -1.0}) {
      Vec3 d = Vec3::Zero();
      d[a] = s;
      dirs[k++] = d;
    }
  }
  for (const double x : {1.0, -1.0}) {
    for (const double y : {1.0, -1.0}) {
      for (const double z : {1.0, -1.0}) dirs[k++] = Vec3(x, y, z).normalized();
    }
  }
  return dirs;
}

std::array<Vec2, kInPlaneDirections> InPlaneDirections() {
  std::array<Vec2, kInPlaneDirections> dirs;
  for (std::size_t k = 0; k < kInPlaneDirections; ++k) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(k) / kInPlaneDirections;
    dirs[k] = Vec2(std::cos(a), std::sin(a));
  }
  return dirs;
}

/// A plane with its inliers projected into an in-plane frame (lengthened to bridge gaps).
struct PlaneOutline {
  Plane3 plane;
  Vec3 u = Vec3::Zero();
  Vec3 w = Vec3::Zero();
  std::vector<Vec2> from;
  std::vector<Vec2> to;
  std::vector<double> on_line_tolerance;  ///< gap_bridge x the inlier's length
  Vec2 min = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 max = Vec2::Constant(-std::numeric_limits<double>::infinity());
  /// The inliers' boxes (Index), or null: the inliers are walked.
  std::shared_ptr<const BoxBvh> index;
  double index_reach = 0.0;  ///< kIndexReach x the in-plane size (Index)

  [[nodiscard]] Vec2 Project(const Vec3& p) const {
    const Vec3 d = p - plane.point;
    return {d.dot(u), d.dot(w)};
  }
  void Add(const Segment3& s, double gap_bridge) {
    const Vec2 a = Project(s.p1);
    const Vec2 b = Project(s.p2);
    const Vec2 grow = gap_bridge * (b - a);
    on_line_tolerance.push_back(grow.norm());
    from.push_back(a - grow);
    to.push_back(b + grow);
    min = min.cwiseMin(from.back()).cwiseMin(to.back());
    max = max.cwiseMax(from.back()).cwiseMax(to.back());
  }
  /// A box that holds every point of the plane that Surrounds may accept (the corners of the
  /// in-plane box, lifted), grown for rounding; empty without inliers.
  [[nodiscard]] Box3 HitBox() const {
    Box3 box;
    if (from.empty()) return box;
    for (const double x : {min.x(), max.x()}) {
      for (const double y : {min.y(), max.y()}) box.Extend(plane.point + x * u + y * w);
    }
    const double scale =
        box.min.cwiseAbs().cwiseMax(box.max.cwiseAbs()).maxCoeff() + box.Extent().maxCoeff();
    box.min.array() -= kHitBoxMargin * scale;
    box.max.array() += kHitBoxMargin * scale;
    return box;
  }
  /// Indexes the inliers (each box grown by its on-line tolerance and by index_reach) when there
  /// are more than kIndexedInliers.
  void Index() {
    if (from.size() <= kIndexedInliers) return;
    index_reach =
        kIndexReach * (min.cwiseAbs().cwiseMax(max.cwiseAbs()).maxCoeff() + (max - min).maxCoeff());
    std::vector<Box3> boxes(from.size());
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (!(Extent(i).squaredNorm() > 0.0)) continue;  // never met: an empty box
      const double grow = on_line_tolerance[i] + index_reach;
      const Vec2 lo = from[i].cwiseMin(to[i]).array() - grow;
      const Vec2 hi = from[i].cwiseMax(to[i]).array() + grow;
      boxes[i].Extend(Vec3(lo.x(), lo.y(), 0.0));
      boxes[i].Extend(Vec3(hi.x(), hi.y(), 0.0));
    }
    index = std::make_shared<const BoxBvh>(boxes);
  }

  /// `h` lies on an inlier, or each in-plane direction from `h` crosses some inlier. The answer
  /// does not depend on the order the inliers are tried in, so the hierarchy gives the walk's.
  [[nodiscard]] bool Surrounds(const Vec2& h,
                               const std::array<Vec2, kInPlaneDirections>& dirs) const {
    if (!((h.array() >= min.array()).all() && (h.array() <= max.array()).all())) return false;
    if (index != nullptr) {
      const Vec3 at(h.x(), h.y(), 0.0);
      Box3 point;
      point.Extend(at);
      if (index->AnyOverlapping(point, [&](std::uint32_t i) { return OnInlier(i, h); })) {
        return true;
      }
      return std::all_of(dirs.begin(), dirs.end(), [&](const Vec2& d) {
        const Vec3 direction(d.x(), d.y(), 0.0);
        return index->AnyAlongRay(at - index_reach * direction, direction, [&](std::uint32_t i) {
          return Crosses(i, h, d);
        });
      });
    }
    std::array<bool, kInPlaneDirections> crossed{};
    std::size_t num_crossed = 0;
    for (std::size_t i = 0; i < from.size() && num_crossed < kInPlaneDirections; ++i) {
      if (OnInlier(i, h)) return true;
      for (std::size_t k = 0; k < kInPlaneDirections; ++k) {
        if (!crossed[k] && Crosses(i, h, dirs[k])) {
          crossed[k] = true;
          ++num_crossed;
        }
      }
    }
    return num_crossed == kInPlaneDirections;
  }

 private:
  [[nodiscard]] Vec2 Extent(std::size_t i) const { return to[i] - from[i]; }

  /// `h` on the lengthened inlier i (within its bridged length): a ray through it meets a line.
  /// An inlier seen end-on (no extent in the plane) is never met.
  [[nodiscard]] bool OnInlier(std::size_t i, const Vec2& h) const {
    const Vec2 e = Extent(i);
    if (!(e.squaredNorm() > 0.0)) return false;
    const Vec2 ah = from[i] - h;
    const double along = std::clamp(-ah.dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (ah + along * e).norm() <= on_line_tolerance[i];
  }

  /// The in-plane ray from `h` along `d` crosses inlier i once.
  [[nodiscard]] bool Crosses(std::size_t i, const Vec2& h, const Vec2& d) const {
    const Vec2 e = Extent(i);
    if (!(e.squaredNorm() > 0.0)) return false;
    const double denom = Cross2(d, e);
    if (std::abs(denom) <= kParallelSine * e.norm()) return false;  // no single crossing
    const Vec2 ah = from[i] - h;
    const double t = Cross2(ah, e) / denom;  // along the direction
    const double s = Cross2(ah, d) / denom;  // along the inlier
    return t > 0.0 && s >= 0.0 && s <= 1.0;
  }
};

std::vector<PlaneOutline> Outlines(const Scene& scene, double gap_bridge) {
  std::vector<PlaneOutline> outlines(scene.planes.size());
  for (std::size_t p = 0; p < outlines.size(); ++p) {
    PlaneOutline& o = outlines[p];
    o.plane = scene.planes[PlaneId(p)];
    o.plane.normal.normalize();
    const Vec3& n = o.plane.normal;
    const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    o.u = n.cross(helper).normalized();
    o.w = n.cross(o.u);
  }
  for (std::size_t s = 0; s < scene.NumSegments(); ++s) {
    const PlaneMembership& m = scene.memberships[SegmentId(s)];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      outlines[m.planes[k].index()].Add(scene.segments[SegmentId(s)], gap_bridge);
    }
  }
  for (PlaneOutline& o : outlines) o.Index();
  return outlines;
}

/// The observing viewpoints (ascending), or `max_viewpoints` of them evenly spaced in that order
/// when there are more; `observing` is set to how many observe.
std::vector<std::size_t> ExaminedViewpoints(const Scene& scene,
                                            std::size_t max_viewpoints,
                                            std::size_t& observing) {
  std::vector<std::uint8_t> observes(scene.viewpoints.size(), 0);
  for (const ViewpointId v : scene.observations.items()) observes[v.index()] = 1;
  std::vector<std::size_t> all;
  for (std::size_t v = 0; v < observes.size(); ++v) {
    if (observes[v] != 0) all.push_back(v);
  }
  observing = all.size();
  const std::size_t n = std::max<std::size_t>(max_viewpoints, 1);
  if (all.size() <= n) return all;
  std::vector<std::size_t> sample(n);
  for (std::size_t i = 0; i < n; ++i) sample[i] = all[i * all.size() / n];
  return sample;
}

}  // namespace

SceneModeDecision DecideSceneMode(const Scene& scene,
                                  const SceneModeOptions& options,
                                  const RunContext& ctx) {
  SceneModeDecision decision;
  const std::vector<std::size_t> examined =
      ExaminedViewpoints(scene, options.max_viewpoints, decision.sampled_from);
  decision.observing_viewpoints = examined.size();
  if (scene.planes.empty() || !scene.HasMemberships() || scene.NumSegments() == 0) {
    decision.reason = "auto: no planes -> exterior";
    return decision;
  }
  const std::vector<PlaneOutline> outlines = Outlines(scene, options.gap_bridge);
  std::vector<Box3> boxes;
  boxes.reserve(outlines.size());
  for (const PlaneOutline& outline : outlines) boxes.push_back(outline.HitBox());
  const BoxBvh bvh(boxes);
  const std::array<Vec3, 14> dirs = RayDirections();
  const std::array<Vec2, kInPlaneDirections> in_plane = InPlaneDirections();
  std::vector<std::uint8_t> enclosed(examined.size(), 0);
  RunInArena(ctx, [&] {
    tbb::parallel_for(std::size_t{0}, examined.size(), [&](std::size_t i) {
      const Vec3& o = scene.viewpoints[ViewpointId(examined[i])];
      int open = 0;
      for (const Vec3& d : dirs) {
        const bool hit = bvh.AnyAlongRay(o, d, [&](std::uint32_t p) {
          const PlaneOutline& outline = outlines[p];
          const double nd = outline.plane.normal.dot(d);
          if (std::abs(nd) < kMinRayPlaneCosine) return false;
          const double t = -outline.plane.SignedDistance(o) / nd;
          return t > 0.0 && outline.Surrounds(outline.Project(o + t * d), in_plane);
        });
        if (!hit && ++open > options.open_rays) break;
      }
      enclosed[i] = open <= options.open_rays ? 1 : 0;
    });
  });
  for (const std::uint8_t e : enclosed) decision.enclosed_viewpoints += e;
  decision.interior = 2 * decision.enclosed_viewpoints > decision.observing_viewpoints;
  const double share = decision.observing_viewpoints == 0
                           ? 0.0
                           : static_cast<double>(decision.enclosed_viewpoints) /
                                 static_cast<double>(decision.observing_viewpoints);
  decision.weak =
      decision.observing_viewpoints > 0 && share >= options.weak_low && share <= options.weak_high;
  std::ostringstream os;
  os << "auto: " << decision.enclosed_viewpoints << " of " << decision.observing_viewpoints;
  if (decision.sampled_from > decision.observing_viewpoints) {
    os << " (an even sample of " << decision.sampled_from << ")";
  }
  os << " viewpoints enclosed by planes (at most " << options.open_rays << " of 14 rays open) -> "
     << (decision.interior ? "interior" : "exterior");
  decision.reason = os.str();
  return decision;
}

}  // namespace linesurf::pipeline
