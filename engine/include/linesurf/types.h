#pragma once
/// @file types.h
/// @brief Plain value types of the linesurf facade: the input scene (segments, viewpoints,
/// observations, optional planes) and the output mesh. No third-party types; world coordinates
/// in scene units (metres for metric scenes) everywhere.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace linesurf {
inline namespace v3 {

/// A point or direction (x, y, z), world coordinates.
using Vector3 = std::array<double, 3>;

/// A 3D line segment between two endpoints.
struct Segment {
  Vector3 p1{};
  Vector3 p2{};
};

/// Viewpoint `viewpoint` (an index into InputScene::viewpoints) observed segment `segment` (an
/// index into InputScene::segments): the sight rays from the viewpoint to the segment are empty
/// space.
struct Observation {
  std::uint32_t segment = 0;
  std::uint32_t viewpoint = 0;
};

/// A plane through `point` with unit `normal`: the points x with normal . (x - point) = 0.
struct Plane {
  Vector3 point{};
  Vector3 normal{0.0, 0.0, 1.0};
};

/// Segment `segment` lies on plane `plane` (an index into a plane list). A segment lies on at
/// most two planes: one = textural line, two = structural line (a crease).
struct Membership {
  std::uint32_t segment = 0;
  std::uint32_t plane = 0;
};

/// @brief A scene as views of the host's arrays (zero-copy). The arrays must stay alive and
/// unchanged during the call that reads them; nothing is kept after it returns.
///
/// Observations may come in any order; those of one segment keep their relative order (which
/// the engine preserves). Indices are checked: one out of range fails the call with
/// kInvalidInput naming the offending entry.
struct InputScene {
  std::span<const Segment> segments;
  /// Camera centres; several observations may share one.
  std::span<const Vector3> viewpoints;
  std::span<const Observation> observations;
  /// Optional planes (used with PlaneSource::kGiven; ignored when detecting).
  std::span<const Plane> planes;
  /// Optional memberships into `planes` (at most two per segment).
  std::span<const Membership> memberships;
};

/// An owning scene, e.g. as read from a file by ReadScene; View() lends it to the calls.
struct SceneData {
  std::vector<Segment> segments;
  std::vector<Vector3> viewpoints;
  /// Sorted by segment (file order within a segment).
  std::vector<Observation> observations;
  std::vector<Plane> planes;
  /// Sorted by segment, then by position in the file.
  std::vector<Membership> memberships;
  /// Every segment has a membership list, possibly empty: ReadScene sets it for a reference
  /// JSON with `planes` or `plane_index` keys (docs/user/formats.md). Kept for writing back, so that
  /// WriteScene writes `plane_index` for every line (and `planes`) even when this scene has no
  /// membership and no plane, as the file had them. Planes imply it.
  bool has_memberships = false;
  /// Per observation, when the file carries them (reference JSON residual_per_pt_view: the 2D
  /// endpoints of the segment in that image, pixels); empty otherwise. Kept for writing back.
  std::vector<std::array<double, 4>> residuals;
  /// Top-level string fields of the file (e.g. "original_L3Dpp_file"), kept for writing back.
  std::vector<std::pair<std::string, std::string>> extra_fields;

  /// A view of this scene's arrays (valid while this object lives and is not modified).
  [[nodiscard]] InputScene View() const noexcept {
    return InputScene{segments, viewpoints, observations, planes, memberships};
  }
};

/// @brief A polygon mesh: convex faces (triangles with ReconstructOptions::triangulate; with
/// merge_coplanar, faces merged across block faces may be non-convex),
/// counter-clockwise seen from outside (normals point from full to empty space).
///
/// Face f uses face_indices[face_offsets[f] .. face_offsets[f + 1]) (indices into vertices).
struct Mesh {
  std::vector<Vector3> vertices;
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;

  [[nodiscard]] std::size_t NumFaces() const noexcept {
    return face_offsets.empty() ? 0 : face_offsets.size() - 1;
  }
};

}  // namespace v3
}  // namespace linesurf
