#include "engine/pipeline/sanitize_scene.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/core/exception.h"

namespace linesurf::pipeline {
namespace {

constexpr const char* kSanitizeSceneStage = "sanitize_scene";

/// Normals whose length differs from 1 by more than this are counted as renormalised; below it
/// the difference is rounding of a unit vector written in decimal (Andalusian: 4e-16).
constexpr double kUnitNormalTolerance = 1e-9;

bool IsUsable(const Vec3& p, double max_abs) {
  return p.allFinite() && p.cwiseAbs().maxCoeff() <= max_abs;
}

std::string Sci(double v) {
  std::ostringstream s;
  s.precision(2);
  s << std::scientific << v;
  return s.str();
}

void Warn(std::vector<std::string>& warnings, std::size_t count, const std::string& text) {
  if (count > 0) warnings.push_back(std::to_string(count) + " " + text);
}

std::vector<std::string> WarningsFor(const SanitizeStats& s, const SanitizeOptions& o,
                                     double min_length) {
  std::vector<std::string> w;
  Warn(w, s.dropped_non_finite_segments,
       "segments dropped: non-finite coordinate or beyond +-" + Sci(o.max_abs_coordinate));
  Warn(w, s.dropped_short_segments,
       "segments dropped: zero or near-zero length (<= " + Sci(min_length) + ")");
  Warn(w, s.dropped_bad_viewpoints,
       "viewpoints dropped: non-finite coordinate or beyond +-" + Sci(o.max_abs_coordinate));
  Warn(w, s.removed_bad_observations,
       "observations removed: viewpoint id out of range or of a dropped viewpoint");
  Warn(w, s.removed_duplicate_views, "observations removed: viewpoint repeated on one segment");
  Warn(w, s.segments_without_views, "segments kept without any view (no visibility evidence)");
  Warn(w, s.dropped_bad_planes, "planes dropped: non-finite, too large or zero-length normal");
  Warn(w, s.renormalised_normals, "plane normals renormalised to unit length");
  Warn(w, s.reanchored_planes,
       "plane points far from the data re-anchored at the plane point nearest the data centre");
  Warn(w, s.removed_bad_memberships,
       "plane_index entries removed: plane out of range or dropped");
  Warn(w, s.removed_repeated_memberships, "plane_index entries removed: plane repeated on one segment");
  Warn(w, s.dropped_residuals, "residuals dropped: inconsistent with the observations or non-finite");
  return w;
}

/// The observation rows and plane memberships, when present, must have one entry a segment.
void CheckRowCounts(const Scene& in) {
  const std::size_t num_segments = in.NumSegments();
  const std::size_t num_rows = in.observations.NumRows();
  LINESURF_THROW_IF(num_rows != 0 && num_rows != num_segments,
                    kInvalidInput,
                    kSanitizeSceneStage,
                    "scene has " << num_rows << " observation rows for " << num_segments
                                 << " segments");
  LINESURF_THROW_IF(in.HasMemberships() && in.memberships.size() != num_segments,
                    kInvalidInput,
                    kSanitizeSceneStage,
                    "scene has " << in.memberships.size() << " plane memberships for "
                                 << num_segments << " segments");
}

/// The new id of `id` under `map`; invalid when `id` is out of range or was dropped.
template <typename Id>
Id Remap(Id id, const IdVector<Id, Id>& map) {
  return id.IsValid() && id.index() < map.size() ? map[id] : Id::Invalid();
}

/// Drops unusable viewpoints, keeping the order of the others; returns old id -> new id.
IdVector<ViewpointId, ViewpointId> KeepViewpoints(const Scene& in,
                                                  double max_abs,
                                                  Scene& out,
                                                  SanitizeStats& stats) {
  IdVector<ViewpointId, ViewpointId> view_map(in.viewpoints.size(), ViewpointId::Invalid());
  for (std::size_t v = 0; v < in.viewpoints.size(); ++v) {
    const Vec3& c = in.viewpoints[ViewpointId(v)];
    if (!IsUsable(c, max_abs)) {
      ++stats.dropped_bad_viewpoints;
      continue;
    }
    view_map[ViewpointId(v)] = out.viewpoints.NextId();
    out.viewpoints.push_back(c);
  }
  return view_map;
}

/// Drops unusable planes and renormalises the others; returns old id -> new id.
IdVector<PlaneId, PlaneId> KeepPlanes(const Scene& in,
                                      const SanitizeOptions& options,
                                      Scene& out,
                                      SanitizeStats& stats) {
  IdVector<PlaneId, PlaneId> plane_map(in.planes.size(), PlaneId::Invalid());
  for (std::size_t p = 0; p < in.planes.size(); ++p) {
    Plane3 plane = in.planes[PlaneId(p)];
    const double length = plane.normal.norm();
    if (!IsUsable(plane.point, options.max_abs_coordinate) || !plane.normal.allFinite() ||
        !std::isfinite(length) || !(length > options.min_normal_length)) {
      ++stats.dropped_bad_planes;
      continue;
    }
    if (std::abs(length - 1.0) > kUnitNormalTolerance) ++stats.renormalised_normals;
    plane.normal /= length;
    plane_map[PlaneId(p)] = out.planes.NextId();
    out.planes.push_back(plane);
  }
  return plane_map;
}

/// Which segments have usable end points, and the length threshold from their scale.
struct SegmentScale {
  std::vector<bool> finite;  ///< per input segment: both end points usable
  double min_length = 0.0;   ///< segments not longer than this are dropped (m)
};

SegmentScale ScaleOfFiniteSegments(const Scene& in,
                                   const SanitizeOptions& options,
                                   SanitizeStats& stats) {
  const std::size_t num_segments = in.NumSegments();
  SegmentScale scale{std::vector<bool>(num_segments, false), 0.0};
  Box3 box;
  for (std::size_t s = 0; s < num_segments; ++s) {
    const Segment3& seg = in.segments[SegmentId(s)];
    scale.finite[s] = IsUsable(seg.p1, options.max_abs_coordinate) &&
                      IsUsable(seg.p2, options.max_abs_coordinate);
    if (!scale.finite[s]) {
      ++stats.dropped_non_finite_segments;
      continue;
    }
    box.Extend(seg.p1);
    box.Extend(seg.p2);
  }
  const double diagonal = box.IsEmpty() ? 0.0 : box.Extent().norm();
  scale.min_length = options.min_segment_length_rel * diagonal;
  return scale;
}

/// The kept views of one segment and their residuals.
struct ViewRow {
  std::vector<ViewpointId> views;
  std::vector<Residual2> residuals;
};

/// Fills `row` with the remapped, first-seen views of segment `id`; while `residuals_ok`, also
/// their residuals, and clears `residuals_ok` at the first non-finite one.
void KeepViews(const Scene& in,
               SegmentId id,
               const IdVector<ViewpointId, ViewpointId>& view_map,
               ViewRow& row,
               bool& residuals_ok,
               SanitizeStats& stats) {
  const auto views = in.observations[id];
  const std::size_t first_item = in.observations.offsets()[id.index()];
  for (std::size_t k = 0; k < views.size(); ++k) {
    const ViewpointId mapped = Remap(views[k], view_map);
    if (!mapped.IsValid()) {
      ++stats.removed_bad_observations;
      continue;
    }
    if (std::find(row.views.begin(), row.views.end(), mapped) != row.views.end()) {
      ++stats.removed_duplicate_views;
      continue;
    }
    row.views.push_back(mapped);
    if (residuals_ok) {
      const Residual2& r = in.residuals[first_item + k];
      residuals_ok = std::isfinite(r[0]) && std::isfinite(r[1]) && std::isfinite(r[2]) &&
                     std::isfinite(r[3]);
      row.residuals.push_back(r);
    }
  }
}

/// The remapped, distinct planes of one membership.
PlaneMembership KeepMembership(const PlaneMembership& m,
                               const IdVector<PlaneId, PlaneId>& plane_map,
                               SanitizeStats& stats) {
  PlaneMembership kept;
  const std::uint8_t count = std::min<std::uint8_t>(m.count, 2);  // the type holds two
  for (std::uint8_t k = 0; k < count; ++k) {
    const PlaneId mapped = Remap(m.planes[k], plane_map);
    if (!mapped.IsValid()) {
      ++stats.removed_bad_memberships;
    } else if (!kept.Add(mapped)) {
      ++stats.removed_repeated_memberships;
    }
  }
  return kept;
}

/// Keeps the finite segments longer than the threshold, with their views, residuals and
/// memberships; residuals are kept only when every one is consistent and finite. Returns the box
/// of the kept segments.
Box3 KeepSegments(const Scene& in,
                  const SegmentScale& scale,
                  const IdVector<ViewpointId, ViewpointId>& view_map,
                  const IdVector<PlaneId, PlaneId>& plane_map,
                  SanitizeResult& result) {
  SanitizeStats& stats = result.stats;
  Scene& out = result.scene;
  const bool no_rows = in.observations.NumRows() == 0;  // a scene built without observations
  const bool keep_residuals = !in.residuals.empty();
  if (keep_residuals && in.residuals.size() != in.observations.NumItems()) {
    stats.dropped_residuals = in.residuals.size();
  }
  bool residuals_ok = keep_residuals && stats.dropped_residuals == 0;
  ViewRow row;
  Box3 kept_box;
  for (std::size_t s = 0; s < in.NumSegments(); ++s) {
    const SegmentId id(s);
    if (!scale.finite[s]) continue;
    const Segment3& seg = in.segments[id];
    if (!(seg.Length() > scale.min_length)) {
      ++stats.dropped_short_segments;
      continue;
    }
    out.segments.push_back(seg);
    result.input_segment.push_back(id);
    kept_box.Extend(seg.p1);
    kept_box.Extend(seg.p2);
    row.views.clear();
    row.residuals.clear();
    if (!no_rows) KeepViews(in, id, view_map, row, residuals_ok, stats);
    if (row.views.empty()) ++stats.segments_without_views;
    out.observations.AddRow(row.views);
    if (residuals_ok) {
      out.residuals.insert(out.residuals.end(), row.residuals.begin(), row.residuals.end());
    }
    if (in.HasMemberships()) {
      out.memberships.push_back(KeepMembership(in.memberships[id], plane_map, stats));
    }
  }
  if (keep_residuals && !residuals_ok) {
    stats.dropped_residuals = in.residuals.size();
    out.residuals.clear();
  }
  return kept_box;
}

/// Fails, naming every reason, when no segment is left.
void ThrowIfNoSegmentLeft(const SanitizeResult& result, std::size_t num_input_segments) {
  if (result.scene.NumSegments() != 0) return;
  std::string why = num_input_segments == 0 ? "the scene has no segments" : "";
  for (const std::string& w : result.warnings) why += (why.empty() ? "" : "; ") + w;
  ThrowError(ErrorCode::kInvalidInput, kSanitizeSceneStage, "no usable segment left (" + why + ")");
}

/// Re-anchors far plane points at the plane point closest to the data centre.
void ReanchorFarPlanes(const Box3& kept_box,
                       const SanitizeOptions& options,
                       Scene& out,
                       SanitizeStats& stats) {
  const Vec3 centre = kept_box.Center();
  const double kept_diagonal = kept_box.Extent().norm();
  for (Plane3& plane : out.planes) {
    if ((plane.point - centre).norm() > options.max_plane_point_distance_rel * kept_diagonal) {
      plane.point = centre - plane.normal * plane.SignedDistance(centre);
      ++stats.reanchored_planes;
    }
  }
}

/// Moves the scene to a frame centred at `centre`, keeping world_from_local consistent.
void Recentre(const Vec3& centre, Scene& out) {
  for (Segment3& seg : out.segments) {
    seg.p1 -= centre;
    seg.p2 -= centre;
  }
  for (Vec3& v : out.viewpoints) v -= centre;
  for (Plane3& plane : out.planes) plane.point -= centre;
  out.world_from_local.translation += out.world_from_local.Rotate(centre);
}

/// Turns the scene into `axes` (columns: the frame's axes in the current coordinates), then
/// recentres it on the centre of its segments' box in that frame.
void TurnToFrame(const Eigen::Matrix3d& axes, Scene& out) {
  const Eigen::Matrix3d local_from_current = axes.transpose();
  Box3 box;
  for (Segment3& seg : out.segments) {
    seg.p1 = local_from_current * seg.p1;
    seg.p2 = local_from_current * seg.p2;
    box.Extend(seg.p1);
    box.Extend(seg.p2);
  }
  for (Vec3& v : out.viewpoints) v = local_from_current * v;
  for (Plane3& plane : out.planes) {
    plane.point = local_from_current * plane.point;
    plane.normal = (local_from_current * plane.normal).normalized();
  }
  out.world_from_local.rotation = out.world_from_local.rotation * axes;
  Recentre(box.Center(), out);
}

}  // namespace

Status SanitizeOptions::Validate() const {
  auto bad = [](const std::string& what) {
    return Error{ErrorCode::kInvalidOptions, kSanitizeSceneStage, "SanitizeOptions." + what};
  };
  if (!(min_segment_length_rel >= 0.0 && min_segment_length_rel < 1.0)) {
    return bad("min_segment_length_rel must be in [0, 1)");
  }
  if (!(max_plane_point_distance_rel > 0.0) || !std::isfinite(max_plane_point_distance_rel)) {
    return bad("max_plane_point_distance_rel must be a finite number > 0");
  }
  if (!(max_abs_coordinate > 0.0) || !std::isfinite(max_abs_coordinate)) {
    return bad("max_abs_coordinate must be a finite number > 0");
  }
  if (!(min_normal_length >= 0.0 && min_normal_length < 1.0)) {
    return bad("min_normal_length must be in [0, 1)");
  }
  return {};
}

Expected<SanitizeResult> SanitizeScene(Scene in, const SanitizeOptions& options) noexcept {
  if (Status valid = options.Validate(); !valid) return valid.error();
  return CatchAll(kSanitizeSceneStage, [&]() -> SanitizeResult {
    CheckRowCounts(in);
    SanitizeResult result;
    SanitizeStats& stats = result.stats;
    Scene& out = result.scene;
    stats.input_segments = in.NumSegments();
    const IdVector<ViewpointId, ViewpointId> view_map =
        KeepViewpoints(in, options.max_abs_coordinate, out, stats);
    const IdVector<PlaneId, PlaneId> plane_map = KeepPlanes(in, options, out, stats);
    const SegmentScale scale = ScaleOfFiniteSegments(in, options, stats);
    const Box3 kept_box = KeepSegments(in, scale, view_map, plane_map, result);
    stats.kept_segments = out.NumSegments();
    result.warnings = WarningsFor(stats, options, scale.min_length);
    ThrowIfNoSegmentLeft(result, in.NumSegments());

    ReanchorFarPlanes(kept_box, options, out, stats);
    result.warnings = WarningsFor(stats, options, scale.min_length);

    out.world_from_local = in.world_from_local;
    out.extra_fields = std::move(in.extra_fields);
    if (options.recentre) {
      Recentre(kept_box.Center(), out);
      if (options.align_to_data_frame) {
        result.frame = EstimateDataFrame(out);
        if (result.frame.found) TurnToFrame(result.frame.axes, out);
      }
    }
    return result;
  });
}

}  // namespace linesurf::pipeline
