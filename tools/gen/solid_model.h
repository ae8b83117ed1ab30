#pragma once
// Ground-truth solids of the synthetic families: closed polyhedra with planar polygon faces, each
// face tagged with its (deduplicated) true plane; sharp edges derived from face adjacency.

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/strong_id.h"

namespace linesurf::synth {

/// One face: vertex indices into its component, counter-clockwise seen from outside (empty
/// space); the polygon is star-shaped from its first vertex (fan triangulation is valid).
struct SolidFace {
  std::vector<std::uint32_t> vertices;
  PlaneId plane;
  Vec3 outward = Vec3::UnitZ();  ///< unit normal pointing from matter to empty space
};

/// A vertex namespace of faces: faces of one component share vertices by index, so the closed
/// 2-manifold property is combinatorial. A component may hold several surfaces (a shell).
struct SolidComponent {
  std::vector<Vec3> vertices;
  std::vector<SolidFace> faces;
};

/// A maximal run of collinear sharp edges between two faces of different true planes.
struct SharpEdge {
  Segment3 segment;
  std::array<PlaneId, 2> planes{};
  std::array<Vec3, 2> outward{Vec3::Zero(), Vec3::Zero()};  ///< outward normals of the two faces
};

/// The ground truth of a family: components plus the deduplicated true planes.
class SolidModel {
 public:
  /// The plane through `point` with unit `normal`, deduplicated up to orientation (the first
  /// orientation seen is kept).
  PlaneId InternPlane(const Vec3& normal, const Vec3& point);
  /// The existing plane through `point` with `normal` (either orientation), or Invalid().
  [[nodiscard]] PlaneId FindPlane(const Vec3& normal, const Vec3& point) const;
  /// Adds a component whose faces have `plane` unset: planes are computed from the polygons.
  void AddComponent(SolidComponent component);
  /// Adds the prism swept by `base` (CCW around `extrusion`, star-shaped from base[0]).
  void AddPrism(std::span<const Vec3> base, const Vec3& extrusion);

  [[nodiscard]] const IdVector<PlaneId, Plane3>& planes() const { return planes_; }
  [[nodiscard]] const std::vector<SolidComponent>& components() const { return components_; }
  /// All components in one mesh (vertex indices offset per component).
  [[nodiscard]] PolygonMesh ToPolygonMesh() const;
  /// Sharp edges merged into maximal collinear runs, ordered by plane pair then position.
  [[nodiscard]] std::vector<SharpEdge> SharpEdges() const;

 private:
  using PlaneKey = std::array<std::int64_t, 4>;
  [[nodiscard]] static PlaneKey KeyOfPlane(const Vec3& normal, const Vec3& point);

  IdVector<PlaneId, Plane3> planes_;
  std::map<PlaneKey, PlaneId> plane_index_;
  std::vector<SolidComponent> components_;
};

/// An axis-aligned box of the rectilinear families (room, floor).
struct AxisBox {
  Vec3 min, max;
  /// Strictly inside.
  [[nodiscard]] bool Contains(const Vec3& p) const {
    return (p.array() > min.array()).all() && (p.array() < max.array()).all();
  }
  [[nodiscard]] double Volume() const { return (max - min).prod(); }
};

/// The box `outer` minus the union of `cavities`, united with `additions` (furniture standing in
/// a cavity), as the full cells of the grid of all their coordinates (RectilinearSolid).
[[nodiscard]] SolidComponent BoxesSolid(const AxisBox& outer, std::span<const AxisBox> cavities,
                                        std::span<const AxisBox> additions);

/// A solid made of the full cells of a rectilinear grid (room shells with niches and furniture).
/// `coords[a]` are the strictly increasing grid coordinates along axis a; `full` labels cell
/// (i, j, k) = [coords[0][i], coords[0][i+1]] x ... at index i + nx * (j + ny * k) with nx, ny the
/// cell counts. Cells outside the grid are empty. Faces are the grid quads between full and empty
/// cells. The caller avoids cells touching only along an edge or at a vertex (not 2-manifold).
[[nodiscard]] SolidComponent RectilinearSolid(const std::array<std::vector<double>, 3>& coords,
                                              const std::vector<std::uint8_t>& full);

}  // namespace linesurf::synth
