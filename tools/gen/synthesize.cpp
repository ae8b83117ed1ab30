#include "tools/gen/synthesize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/core/exception.h"
#include "tools/gen/family_layout.h"
#include "tools/gen/occluder.h"

namespace linesurf::synth {
namespace {

const char* const kSynthesizeStage = "synthesize";
/// A viewpoint sees a line only if it is in front of one of the line's faces by at least this
/// sine of the viewing angle (grazing views are not reconstructed by real pipelines).
constexpr double kMinViewSine = 0.05;
/// Sample points along a piece that must all be visible (ends inset so they stay on the edge).
constexpr double kSampleParams[] = {0.5, 0.02, 0.98};
/// At most this many candidate viewpoints (nearest first) are ray-tested per piece.
constexpr std::size_t kMaxTestedViewpoints = 64;
/// Grain of the parallel visibility loop (pieces per task); results do not depend on it.
constexpr std::size_t kVisibilityGrain = 64;
/// Bounds of the spec fields.
constexpr int kMaxCityBuildings = 100000;
constexpr int kDefaultCityBuildings = 16;
constexpr double kMaxNoise = 10.0;
constexpr double kMaxOutlierFraction = 0.9;
constexpr int kMaxOutlierCount = 1000000;
constexpr int kMaxPieces = 16;
constexpr double kMaxTrim = 0.4;
constexpr int kMaxViews = 64;
constexpr double kMaxOffset = 1e7;
constexpr double kMinScale = 1e-3;
constexpr double kMaxScale = 1e3;
constexpr double kMaxRotationDegrees = 360.0;
constexpr double kMaxViewTrim = 0.45;
/// The reference converter shrinks every sub-segment by 5 % of its length, 2.5 % at each end.
constexpr double kResidualShrink = 0.025;

/// A piece of a true line after cutting and trimming.
struct Piece {
  Segment3 segment;
  std::uint32_t line = 0;
};

/// Viewpoints bucketed in an xy grid of cell = max distance (or one bucket when unbounded).
class ViewpointIndex {
 public:
  ViewpointIndex(const std::vector<Vec3>& viewpoints, double max_distance)
      : viewpoints_(viewpoints), max_distance_(max_distance) {
    if (!std::isfinite(max_distance_)) return;
    for (std::uint32_t i = 0; i < viewpoints.size(); ++i) {
      buckets_[CellOf(viewpoints[i])].push_back(i);
    }
  }
  /// Viewpoints within the max distance of `p` that pass `keep`, nearest first (ties by id).
  template <typename Keep>
  void Near(const Vec3& p, std::vector<std::pair<double, std::uint32_t>>& out, Keep&& keep) const {
    out.clear();
    const double max2 = max_distance_ * max_distance_;
    const auto consider = [&](std::uint32_t i) {
      const double d2 = (viewpoints_[i] - p).squaredNorm();
      if (d2 <= max2 && keep(viewpoints_[i])) out.emplace_back(d2, i);
    };
    if (!std::isfinite(max_distance_)) {
      for (std::uint32_t i = 0; i < viewpoints_.size(); ++i) consider(i);
    } else {
      const auto [cx, cy] = CellOf(p);
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = buckets_.find({cx + dx, cy + dy});
          if (it == buckets_.end()) continue;
          for (std::uint32_t i : it->second) consider(i);
        }
      }
    }
    std::sort(out.begin(), out.end());
  }
  void Near(const Vec3& p, std::vector<std::pair<double, std::uint32_t>>& out) const {
    Near(p, out, [](const Vec3&) { return true; });
  }

 private:
  [[nodiscard]] std::pair<std::int64_t, std::int64_t> CellOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / max_distance_)),
            static_cast<std::int64_t>(std::floor(p.y() / max_distance_))};
  }
  const std::vector<Vec3>& viewpoints_;
  double max_distance_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>> buckets_;
};

/// Three draws `draw(axis)` made in the order z, y, x. C++ leaves the order of the arguments of
/// `Vec3(draw(), draw(), draw())` unspecified (g++ went right to left, clang left to right, so
/// the two made different scenes from one seed); z, y, x keeps the scenes g++ made.
template <typename Draw>
Vec3 DrawZyx(Draw&& draw) {
  const double z = draw(2);
  const double y = draw(1);
  const double x = draw(0);
  return Vec3(x, y, z);
}

Vec3 UniformInCube(Rng& rng) {
  return DrawZyx([&](int) { return rng.Uniform(-1, 1); });
}

Vec3 UniformInBall(Rng& rng, double radius) {
  while (true) {
    const Vec3 p = UniformInCube(rng);
    if (p.squaredNorm() <= 1.0) return radius * p;
  }
}

Vec3 UniformDirection(Rng& rng) {
  while (true) {
    const Vec3 p = UniformInCube(rng);
    const double n2 = p.squaredNorm();
    if (n2 <= 1.0 && n2 > 1e-6) return p / std::sqrt(n2);
  }
}

FamilyLayout MakeLayout(const SynthSpec& spec) {
  if (spec.family == "cube") return CubeLayout(spec);
  if (spec.family == "house") return HouseLayout(spec);
  if (spec.family == "room") return RoomLayout(spec);
  if (spec.family == "lshape") return LShapeLayout(spec);
  if (spec.family == "floor") return FloorLayout(spec);
  return CityLayout(spec);
}

/// Cuts line `index` into 1..max_pieces pieces and trims each end.
void CutLine(const TrueLine& line, std::uint32_t index, const SynthSpec& spec, int max_pieces,
             double max_trim, double min_piece, std::vector<Piece>& out) {
  Rng rng = StreamRng(spec.seed, SynthStream::kCut, index);
  const double length = line.segment.Length();
  int pieces = 1 + static_cast<int>(rng.Below(static_cast<std::uint64_t>(max_pieces)));
  pieces = std::max(1, std::min(pieces, static_cast<int>(std::floor(length / min_piece))));
  std::vector<double> cuts = {0.0, 1.0};
  for (int i = 1; i < pieces; ++i) cuts.push_back(rng.Uniform());
  std::sort(cuts.begin(), cuts.end());
  const Vec3 d = line.segment.p2 - line.segment.p1;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double span = cuts[i + 1] - cuts[i];
    const double t0 = cuts[i] + span * rng.Uniform(0.0, max_trim);
    const double t1 = cuts[i + 1] - span * rng.Uniform(0.0, max_trim);
    if ((t1 - t0) * length <= 0.0) continue;
    out.push_back(Piece{Segment3{line.segment.p1 + t0 * d, line.segment.p1 + t1 * d}, index});
  }
}

/// Unit mean of the directions from the segment's midpoint to its viewpoints.
Vec3 MeanViewDirection(const Segment3& s, const std::vector<std::uint32_t>& views,
                       const std::vector<Vec3>& viewpoints) {
  Vec3 sum = Vec3::Zero();
  for (std::uint32_t v : views) sum += (viewpoints[v] - s.Midpoint()).normalized();
  return sum.norm() > 0.0 ? Vec3(sum.normalized()) : Vec3::UnitZ();
}

Vec3 EndpointNoise(const SynthSpec& spec, const Vec3& depth, Rng& rng) {
  switch (spec.noise_model) {
    case NoiseModel::kGaussian:
      return spec.noise_sigma * DrawZyx([&](int) { return rng.Normal(); });
    case NoiseModel::kUniformBall:
      return UniformInBall(rng, spec.noise_sigma);
    case NoiseModel::kDepth: {
      // Variances s^2/2, s^2/2 across and 2 s^2 along the depth: 3 s^2 in total.
      const Vec3 a = depth.unitOrthogonal();
      const Vec3 b = depth.cross(a);
      const double across = spec.noise_sigma / std::sqrt(2.0);
      // Drawn along, b, a: the order g++ evaluated the single expression in (see DrawZyx).
      const double along = rng.Normal();
      const double along_b = rng.Normal();
      const double along_a = rng.Normal();
      return across * (along_a * a + along_b * b) +
             std::sqrt(2.0) * spec.noise_sigma * along * depth;
    }
  }
  return Vec3::Zero();
}

/// A false match: a copy of a random kept piece (of the first `pieces` segments) moved along its
/// mean viewing direction by 0.1..1 m either way and turned by up to 15 degrees about its
/// midpoint, with the piece's views.
void AddNearOutlier(Scene& scene, std::size_t pieces, Rng& rng, SyntheticScene& out) {
  constexpr double kMinShift = 0.1, kMaxShift = 1.0, kMaxTurnRad = 15.0 * 3.14159265358979 / 180.0;
  const SegmentId source(static_cast<std::size_t>(rng.Below(pieces)));
  const Segment3 piece = scene.segments[source];
  const std::vector<ViewpointId> row(scene.observations[source].begin(),
                                     scene.observations[source].end());
  Vec3 depth = Vec3::Zero();
  for (ViewpointId v : row) depth += (scene.viewpoints[v] - piece.Midpoint()).normalized();
  depth = depth.norm() > 0.0 ? Vec3(depth.normalized()) : Vec3::UnitZ();
  const double distance = rng.Uniform(kMinShift, kMaxShift);
  const double shift = rng.Below(2) == 0 ? -distance : distance;
  const Vec3 axis = UniformDirection(rng);
  const Eigen::AngleAxisd turn(rng.Uniform(-kMaxTurnRad, kMaxTurnRad), axis);
  const Vec3 mid = piece.Midpoint() + shift * depth;
  const Vec3 half = turn * (0.5 * (piece.p2 - piece.p1));
  scene.segments.push_back(Segment3{mid - half, mid + half});
  scene.observations.AddRow(row);
  scene.memberships.push_back(PlaneMembership{});
  out.kinds.push_back(SegmentKind::kOutlier);
}

/// One sub-segment per (segment, view), on the segment's line, with that view only; segment
/// order kept, sub-segments in view order.
void SplitByObservation(const SynthSpec& spec, SyntheticScene& out) {
  Scene& in = out.scene;
  Scene split;
  split.viewpoints = in.viewpoints;
  split.planes = in.planes;
  std::vector<SegmentKind> kinds;
  std::uint64_t observation = 0;
  for (std::size_t i = 0; i < in.NumSegments(); ++i) {
    const SegmentId s(i);
    const Segment3& seg = in.segments[s];
    const Vec3 d = seg.p2 - seg.p1;
    for (ViewpointId v : in.observations[s]) {
      Rng rng = StreamRng(spec.seed, SynthStream::kSplit, observation++);
      double t0 = rng.Uniform(0.0, spec.max_view_trim);
      double t1 = 1.0 - rng.Uniform(0.0, spec.max_view_trim);
      const double shrink = kResidualShrink * (t1 - t0);
      t0 += shrink;
      t1 -= shrink;
      split.segments.push_back(Segment3{seg.p1 + t0 * d, seg.p1 + t1 * d});
      const std::array<ViewpointId, 1> row{v};
      split.observations.AddRow(row);
      split.memberships.push_back(in.memberships[s]);
      kinds.push_back(out.kinds[i]);
    }
  }
  in = std::move(split);
  out.kinds = std::move(kinds);
}

/// The true lines of a layout: its sharp edges (structural) first, then its texture lines.
std::vector<TrueLine> TrueLines(const FamilyLayout& layout) {
  std::vector<TrueLine> lines;
  for (const SharpEdge& e : layout.solid.SharpEdges()) {
    TrueLine line;
    line.segment = e.segment;
    line.kind = SegmentKind::kStructural;
    line.planes.Add(e.planes[0]);
    line.planes.Add(e.planes[1]);
    line.outward = e.outward;
    lines.push_back(line);
  }
  lines.insert(lines.end(), layout.texture_lines.begin(), layout.texture_lines.end());
  return lines;
}

/// Occlusion-correct views of every piece, sorted: the nearest viewpoints (at most
/// spec.max_views) in front of one of its line's faces that see every sample point of it.
std::vector<std::vector<std::uint32_t>> VisibleViews(const std::vector<Piece>& pieces,
                                                     const std::vector<TrueLine>& lines,
                                                     const FamilyLayout& layout,
                                                     const ViewpointIndex& index,
                                                     const SynthSpec& spec) {
  const Occluder occluder(layout.solid);
  std::vector<std::vector<std::uint32_t>> views(pieces.size());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, pieces.size(), kVisibilityGrain),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<std::pair<double, std::uint32_t>> near;
        std::vector<std::uint32_t> scratch;
        for (std::size_t pi = range.begin(); pi != range.end(); ++pi) {
          const Piece& piece = pieces[pi];
          const TrueLine& line = lines[piece.line];
          const Vec3 mid = piece.segment.Midpoint();
          // Only viewpoints in front of one of the line's faces, at a non-grazing angle.
          index.Near(mid, near, [&](const Vec3& eye) {
            const Vec3 to_eye = eye - mid;
            for (std::uint8_t k = 0; k < line.planes.count; ++k) {
              if (line.outward[k].dot(to_eye) > kMinViewSine * to_eye.norm()) return true;
            }
            return false;
          });
          std::size_t tested = 0;
          for (const auto& [d2, vi] : near) {
            if (views[pi].size() >= static_cast<std::size_t>(spec.max_views)) break;
            const Vec3& eye = layout.viewpoints[vi];
            if (++tested > kMaxTestedViewpoints) break;
            bool clear = true;
            for (double s : kSampleParams) {
              const Vec3 target = piece.segment.p1 + s * (piece.segment.p2 - piece.segment.p1);
              if (!occluder.IsClear(eye, target, scratch)) {
                clear = false;
                break;
              }
            }
            if (clear) views[pi].push_back(vi);
          }
          std::sort(views[pi].begin(), views[pi].end());
        }
      });
  return views;
}

/// The pieces some viewpoint sees, with their endpoint noise, views and true planes; hidden ones
/// are counted in out.num_hidden_dropped.
void AddVisiblePieces(const std::vector<Piece>& pieces,
                      const std::vector<TrueLine>& lines,
                      const std::vector<std::vector<std::uint32_t>>& views,
                      const FamilyLayout& layout,
                      const SynthSpec& spec,
                      SyntheticScene& out) {
  Scene& scene = out.scene;
  std::vector<ViewpointId> row;
  for (std::size_t pi = 0; pi < pieces.size(); ++pi) {
    if (views[pi].empty()) {
      ++out.num_hidden_dropped;
      continue;
    }
    Rng rng = StreamRng(spec.seed, SynthStream::kNoise, pi);
    Segment3 s = pieces[pi].segment;
    if (spec.noise_sigma > 0.0) {
      const Vec3 depth = MeanViewDirection(s, views[pi], layout.viewpoints);
      for (Vec3* p : {&s.p1, &s.p2}) *p += EndpointNoise(spec, depth, rng);
    }
    scene.segments.push_back(s);
    row.clear();
    for (std::uint32_t vi : views[pi]) row.push_back(ViewpointId(vi));
    scene.observations.AddRow(row);
    const TrueLine& line = lines[pieces[pi].line];
    scene.memberships.push_back(line.planes);
    out.kinds.push_back(line.kind);
  }
}

/// The outliers of `spec` after the `inliers` segments of out.scene, each seen by its nearest
/// viewpoints (no occlusion test: they are not geometry).
void AddOutliers(const FamilyLayout& layout,
                 const ViewpointIndex& index,
                 const SynthSpec& spec,
                 SyntheticScene& out) {
  Scene& scene = out.scene;
  const std::size_t inliers = scene.segments.size();
  const std::size_t num_outliers =
      spec.outlier_count
          ? static_cast<std::size_t>(*spec.outlier_count)
          : static_cast<std::size_t>(std::llround(spec.outlier_fraction /
                                                  (1.0 - spec.outlier_fraction) *
                                                  static_cast<double>(inliers)));
  const ViewpointIndex all_views(layout.viewpoints, std::numeric_limits<double>::infinity());
  std::vector<std::pair<double, std::uint32_t>> near;
  std::vector<ViewpointId> row;
  for (std::size_t o = 0; o < num_outliers; ++o) {
    Rng rng = StreamRng(spec.seed, SynthStream::kOutlier, o);
    if (spec.outlier_model == OutlierModel::kNear && inliers > 0) {
      AddNearOutlier(scene, inliers, rng, out);
      continue;
    }
    Segment3 s;
    const OutlierRegion& region = layout.outliers;
    if (region.ball) {
      s.p1 = region.centre + UniformInBall(rng, region.radius);
      s.p2 = region.centre + UniformInBall(rng, region.radius);
    } else {
      s.p1 = DrawZyx(
          [&](int axis) { return rng.Uniform(region.box.min[axis], region.box.max[axis]); });
      // The direction first: the order g++ evaluated the single expression in (see DrawZyx).
      const Vec3 direction = UniformDirection(rng);
      s.p2 = s.p1 + rng.Uniform(region.min_length, region.max_length) * direction;
    }
    const std::size_t wanted = 1 + rng.Below(static_cast<std::uint64_t>(spec.max_views));
    index.Near(s.Midpoint(), near);
    if (near.empty()) all_views.Near(s.Midpoint(), near);
    row.clear();
    for (std::size_t k = 0; k < near.size() && k < wanted; ++k) row.push_back(ViewpointId(near[k].second));
    std::sort(row.begin(), row.end());
    scene.segments.push_back(s);
    scene.observations.AddRow(row);
    scene.memberships.push_back(PlaneMembership{});
    out.kinds.push_back(SegmentKind::kOutlier);
  }
}

/// The frame of the spec: x -> R (scale x) with R the rotation of spec (identity by default).
Eigen::Matrix3d FrameRotation(const SynthSpec& spec) {
  const Vec3 axis(spec.rotation_axis[0], spec.rotation_axis[1], spec.rotation_axis[2]);
  return Eigen::AngleAxisd(spec.rotation_degrees * std::numbers::pi / 180.0, axis.normalized())
      .toRotationMatrix();
}

/// Scales and turns everything about the origin (spec.scale, spec.rotation_*); the default frame
/// leaves every bit as it is.
void ApplyScaleAndRotation(const SynthSpec& spec, SyntheticScene& out) {
  if (spec.scale == 1.0 && spec.rotation_degrees == 0.0) return;
  const Eigen::Matrix3d rotation = FrameRotation(spec);
  const auto move = [&](const Vec3& p) -> Vec3 { return rotation * (spec.scale * p); };
  for (Segment3& s : out.scene.segments) {
    s.p1 = move(s.p1);
    s.p2 = move(s.p2);
  }
  for (Vec3& v : out.scene.viewpoints) v = move(v);
  for (Plane3& p : out.scene.planes) {
    p.point = move(p.point);
    p.normal = (rotation * p.normal).normalized();
  }
  for (Vec3& v : out.ground_truth.vertices) v = move(v);
  out.ground_truth_volume *= spec.scale * spec.scale * spec.scale;
}

/// Moves everything by spec.offset along x and y (georeferenced-like coordinates).
void ApplyOffset(const SynthSpec& spec, SyntheticScene& out) {
  if (spec.offset == 0.0) return;
  const Vec3 shift(spec.offset, spec.offset, 0.0);
  for (Segment3& s : out.scene.segments) {
    s.p1 += shift;
    s.p2 += shift;
  }
  for (Vec3& v : out.scene.viewpoints) v += shift;
  for (Plane3& p : out.scene.planes) p.point += shift;
  for (Vec3& v : out.ground_truth.vertices) v += shift;
}

SyntheticScene Build(const SynthSpec& spec) {
  FamilyLayout layout = MakeLayout(spec);
  const int max_pieces = spec.max_pieces.value_or(layout.default_max_pieces);
  const double max_trim = spec.max_trim.value_or(layout.default_max_trim);
  const std::vector<TrueLine> lines = TrueLines(layout);
  std::vector<Piece> pieces;
  for (std::uint32_t i = 0; i < lines.size(); ++i) {
    CutLine(lines[i], i, spec, max_pieces, max_trim, layout.min_piece_length, pieces);
  }
  const ViewpointIndex index(layout.viewpoints, layout.max_view_distance);
  const std::vector<std::vector<std::uint32_t>> views =
      VisibleViews(pieces, lines, layout, index, spec);

  SyntheticScene out;
  out.spec = spec;
  out.interior = layout.interior;
  out.ground_truth_volume = layout.volume;
  for (const Vec3& v : layout.viewpoints) out.scene.viewpoints.push_back(v);
  out.scene.planes = layout.solid.planes();
  AddVisiblePieces(pieces, lines, views, layout, spec, out);
  AddOutliers(layout, index, spec, out);
  if (spec.residual_split) SplitByObservation(spec, out);
  out.ground_truth = layout.solid.ToPolygonMesh();
  ApplyScaleAndRotation(spec, out);
  ApplyOffset(spec, out);
  out.true_planes = out.scene.planes.raw();
  return out;
}

}  // namespace

std::array<std::size_t, 3> CountKinds(const std::vector<SegmentKind>& kinds) noexcept {
  std::array<std::size_t, 3> counts{0, 0, 0};
  for (const SegmentKind k : kinds) ++counts[static_cast<std::size_t>(k)];
  return counts;
}

const char* SegmentKindName(SegmentKind kind) noexcept {
  switch (kind) {
    case SegmentKind::kStructural:
      return "structural";
    case SegmentKind::kTextural:
      return "textural";
    case SegmentKind::kOutlier:
      return "outlier";
  }
  return "unknown";
}

Status SynthSpec::Validate() const {
  return CatchAll(kSynthesizeStage, [&] {
    LINESURF_THROW_IF(
        family != "cube" && family != "house" && family != "room" && family != "lshape" &&
            family != "floor" && family != "city",
        kInvalidOptions,
        kSynthesizeStage,
        "family: unknown family '" << family << "' (cube, house, lshape, room, floor, city)");
    LINESURF_THROW_IF(size < 0 || size > kMaxCityBuildings,
                      kInvalidOptions,
                      kSynthesizeStage,
                      "size: " << size << " is outside [0, " << kMaxCityBuildings << "]");
    LINESURF_THROW_IF(!(noise_sigma >= 0.0 && noise_sigma <= kMaxNoise),
                      kInvalidOptions,
                      kSynthesizeStage,
                      "noise_sigma: " << noise_sigma << " is outside [0, " << kMaxNoise << "]");
    LINESURF_THROW_IF(!(outlier_fraction >= 0.0 && outlier_fraction <= kMaxOutlierFraction),
                      kInvalidOptions,
                      kSynthesizeStage,
                      "outlier_fraction: " << outlier_fraction << " is outside [0, "
                                           << kMaxOutlierFraction << "]");
    LINESURF_THROW_IF(
        outlier_count && (*outlier_count < 0 || *outlier_count > kMaxOutlierCount),
        kInvalidOptions,
        kSynthesizeStage,
        "outlier_count: " << *outlier_count << " is outside [0, " << kMaxOutlierCount << "]");
    LINESURF_THROW_IF(max_pieces && (*max_pieces < 1 || *max_pieces > kMaxPieces),
                      kInvalidOptions,
                      kSynthesizeStage,
                      "max_pieces: " << *max_pieces << " is outside [1, " << kMaxPieces << "]");
    LINESURF_THROW_IF(max_trim && !(*max_trim >= 0.0 && *max_trim <= kMaxTrim),
                      kInvalidOptions,
                      kSynthesizeStage,
                      "max_trim: " << *max_trim << " is outside [0, " << kMaxTrim << "]");
    LINESURF_THROW_IF(max_views < 1 || max_views > kMaxViews,
                      kInvalidOptions,
                      kSynthesizeStage,
                      "max_views: " << max_views << " is outside [1, " << kMaxViews << "]");
    LINESURF_THROW_IF(
        !(max_view_trim >= 0.0 && max_view_trim <= kMaxViewTrim),
        kInvalidOptions,
        kSynthesizeStage,
        "max_view_trim: " << max_view_trim << " is outside [0, " << kMaxViewTrim << "]");
    LINESURF_THROW_IF(
        !(std::abs(offset) <= kMaxOffset),
        kInvalidOptions,
        kSynthesizeStage,
        "offset: " << offset << " is outside [-" << kMaxOffset << ", " << kMaxOffset << "]");
    LINESURF_THROW_IF(!(scale >= kMinScale && scale <= kMaxScale), kInvalidOptions,
                      kSynthesizeStage,
                      "scale: " << scale << " is outside [" << kMinScale << ", " << kMaxScale
                                << "]");
    const Vec3 axis(rotation_axis[0], rotation_axis[1], rotation_axis[2]);
    LINESURF_THROW_IF(!axis.allFinite() || axis.norm() == 0.0, kInvalidOptions, kSynthesizeStage,
                      "rotation_axis: must be finite and not zero");
    LINESURF_THROW_IF(!(std::abs(rotation_degrees) <= kMaxRotationDegrees), kInvalidOptions,
                      kSynthesizeStage,
                      "rotation_degrees: " << rotation_degrees << " is outside [-"
                                           << kMaxRotationDegrees << ", " << kMaxRotationDegrees
                                           << "]");
  });
}

std::array<double, 3> UpDirection(const SynthSpec& spec) {
  const Vec3 up = FrameRotation(spec) * Vec3::UnitZ();
  return {up.x(), up.y(), up.z()};
}

int CityBuildingCount(const SynthSpec& spec) {
  return spec.size > 0 ? spec.size : kDefaultCityBuildings;
}

Expected<SyntheticScene> Synthesize(const SynthSpec& spec) noexcept {
  if (Status valid = spec.Validate(); !valid) return valid.error();
  return CatchAll(kSynthesizeStage, [&] { return Build(spec); });
}

}  // namespace linesurf::synth
