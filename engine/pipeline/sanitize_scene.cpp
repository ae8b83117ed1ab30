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
    const std::size_t num_segments = in.NumSegments();
    const bool no_rows = in.observations.NumRows() == 0;  // a scene built without observations
    LINESURF_THROW_IF(!no_rows && in.observations.NumRows() != num_segments,
                      kInvalidInput,
                      kSanitizeSceneStage,
                      "scene has " << in.observations.NumRows() << " observation rows for "
                                   << num_segments << " segments");
    LINESURF_THROW_IF(in.HasMemberships() && in.memberships.size() != num_segments,
                      kInvalidInput,
                      kSanitizeSceneStage,
                      "scene has " << in.memberships.size() << " plane memberships for "
                                   << num_segments << " segments");
    SanitizeResult result;
    SanitizeStats& stats = result.stats;
    stats.input_segments = num_segments;
    const double max_abs = options.max_abs_coordinate;

    // Viewpoints: drop unusable ones, keep the order of the others.
    IdVector<ViewpointId, ViewpointId> view_map(in.viewpoints.size(), ViewpointId::Invalid());
    Scene& out = result.scene;
    for (std::size_t v = 0; v < in.viewpoints.size(); ++v) {
      const Vec3& c = in.viewpoints[ViewpointId(v)];
      if (!IsUsable(c, max_abs)) {
        ++stats.dropped_bad_viewpoints;
        continue;
      }
      view_map[ViewpointId(v)] = out.viewpoints.NextId();
      out.viewpoints.push_back(c);
    }

    // Planes: drop unusable ones, renormalise the others.
    IdVector<PlaneId, PlaneId> plane_map(in.planes.size(), PlaneId::Invalid());
    for (std::size_t p = 0; p < in.planes.size(); ++p) {
      Plane3 plane = in.planes[PlaneId(p)];
      const double length = plane.normal.norm();
      if (!IsUsable(plane.point, max_abs) || !plane.normal.allFinite() || !std::isfinite(length) ||
          !(length > options.min_normal_length)) {
        ++stats.dropped_bad_planes;
        continue;
      }
      if (std::abs(length - 1.0) > kUnitNormalTolerance) ++stats.renormalised_normals;
      plane.normal /= length;
      plane_map[PlaneId(p)] = out.planes.NextId();
      out.planes.push_back(plane);
    }

    // Segments: scene scale from the finite ones, then the length threshold.
    std::vector<bool> finite(num_segments, false);
    Box3 box;
    for (std::size_t s = 0; s < num_segments; ++s) {
      const Segment3& seg = in.segments[SegmentId(s)];
      finite[s] = IsUsable(seg.p1, max_abs) && IsUsable(seg.p2, max_abs);
      if (!finite[s]) {
        ++stats.dropped_non_finite_segments;
        continue;
      }
      box.Extend(seg.p1);
      box.Extend(seg.p2);
    }
    const double diagonal = box.IsEmpty() ? 0.0 : box.Extent().norm();
    const double min_length = options.min_segment_length_rel * diagonal;

    const bool keep_residuals = !in.residuals.empty();
    if (keep_residuals && in.residuals.size() != in.observations.NumItems()) {
      stats.dropped_residuals = in.residuals.size();
    }
    bool residuals_ok = keep_residuals && stats.dropped_residuals == 0;
    std::vector<ViewpointId> row;
    std::vector<Residual2> row_residuals;
    Box3 kept_box;
    for (std::size_t s = 0; s < num_segments; ++s) {
      const SegmentId id(s);
      if (!finite[s]) continue;
      const Segment3& seg = in.segments[id];
      if (!(seg.Length() > min_length)) {
        ++stats.dropped_short_segments;
        continue;
      }
      out.segments.push_back(seg);
      result.input_segment.push_back(id);
      kept_box.Extend(seg.p1);
      kept_box.Extend(seg.p2);
      row.clear();
      row_residuals.clear();
      if (!no_rows) {
        const auto views = in.observations[id];
        const std::size_t first_item = in.observations.offsets()[s];
        for (std::size_t k = 0; k < views.size(); ++k) {
          const ViewpointId v = views[k];
          const ViewpointId mapped =
              v.IsValid() && v.index() < view_map.size() ? view_map[v] : ViewpointId::Invalid();
          if (!mapped.IsValid()) {
            ++stats.removed_bad_observations;
            continue;
          }
          if (std::find(row.begin(), row.end(), mapped) != row.end()) {
            ++stats.removed_duplicate_views;
            continue;
          }
          row.push_back(mapped);
          if (residuals_ok) {
            const Residual2& r = in.residuals[first_item + k];
            residuals_ok = std::isfinite(r[0]) && std::isfinite(r[1]) && std::isfinite(r[2]) &&
                           std::isfinite(r[3]);
            row_residuals.push_back(r);
          }
        }
      }
      if (row.empty()) ++stats.segments_without_views;
      out.observations.AddRow(row);
      if (residuals_ok) {
        out.residuals.insert(out.residuals.end(), row_residuals.begin(), row_residuals.end());
      }
      if (in.HasMemberships()) {
        const PlaneMembership& m = in.memberships[id];
        PlaneMembership kept;
        const std::uint8_t count = std::min<std::uint8_t>(m.count, 2);  // the type holds two
        for (std::uint8_t k = 0; k < count; ++k) {
          const PlaneId p = m.planes[k];
          const PlaneId mapped =
              p.IsValid() && p.index() < plane_map.size() ? plane_map[p] : PlaneId::Invalid();
          if (!mapped.IsValid()) {
            ++stats.removed_bad_memberships;
          } else if (!kept.Add(mapped)) {
            ++stats.removed_repeated_memberships;
          }
        }
        out.memberships.push_back(kept);
      }
    }
    if (keep_residuals && !residuals_ok) {
      stats.dropped_residuals = in.residuals.size();
      out.residuals.clear();
    }
    stats.kept_segments = out.NumSegments();
    result.warnings = WarningsFor(stats, options, min_length);
    if (out.NumSegments() == 0) {
      std::string why = num_segments == 0 ? "the scene has no segments" : "";
      for (const std::string& w : result.warnings) why += (why.empty() ? "" : "; ") + w;
      ThrowError(
          ErrorCode::kInvalidInput, kSanitizeSceneStage, "no usable segment left (" + why + ")");
    }

    // Re-anchor far plane points at the plane point closest to the data centre.
    const Vec3 centre = kept_box.Center();
    const double kept_diagonal = kept_box.Extent().norm();
    for (Plane3& plane : out.planes) {
      if ((plane.point - centre).norm() > options.max_plane_point_distance_rel * kept_diagonal) {
        plane.point = centre - plane.normal * plane.SignedDistance(centre);
        ++stats.reanchored_planes;
      }
    }
    result.warnings = WarningsFor(stats, options, min_length);

    out.world_from_local = in.world_from_local;
    out.extra_fields = std::move(in.extra_fields);
    if (options.recentre) {
      for (Segment3& seg : out.segments) {
        seg.p1 -= centre;
        seg.p2 -= centre;
      }
      for (Vec3& v : out.viewpoints) v -= centre;
      for (Plane3& plane : out.planes) plane.point -= centre;
      out.world_from_local.translation += centre;
    }
    return result;
  });
}

}  // namespace linesurf::pipeline
