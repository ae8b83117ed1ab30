#include "engine/pipeline/mesh_topology.h"

#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <tuple>
#include <vector>

namespace linesurf::pipeline {
namespace {

/// Faces of the CSR layout PolygonMesh uses.
class FaceList {
 public:
  FaceList(std::span<const std::uint32_t> offsets, std::span<const std::uint32_t> indices)
      : offsets_(offsets), indices_(indices) {}
  [[nodiscard]] std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  [[nodiscard]] std::span<const std::uint32_t> operator[](std::size_t f) const {
    return indices_.subspan(offsets_[f], offsets_[f + 1] - offsets_[f]);
  }

 private:
  std::span<const std::uint32_t> offsets_;
  std::span<const std::uint32_t> indices_;
};

/// Signed volume over a fan of every face: exact for any closed polygon mesh because the fan's
/// inner edges cancel.
double SignedVolume(std::span<const Vec3> vertices, const FaceList& faces) {
  double volume = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto face = faces[f];
    if (face.size() < 3) continue;
    const Vec3& a = vertices[face[0]];
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      volume += a.dot(vertices[face[k]].cross(vertices[face[k + 1]])) / 6.0;
    }
  }
  return volume;
}

/// Counts boundary, non-manifold and unpaired edges and the components in `t`, and whether every
/// edge used twice is used once in each direction.
void CheckEdges(const FaceList& faces, MeshTopology& t) {
  // Directed edges (lo, hi, forward, face) sorted: groups are undirected edges.
  struct HalfEdge {
    std::size_t lo, hi;
    bool forward;
    std::size_t face;
    auto Key() const { return std::tie(lo, hi, forward, face); }
  };
  std::vector<HalfEdge> edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto face = faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::size_t a = face[k];
      const std::size_t b = face[(k + 1) % face.size()];
      edges.push_back({std::min(a, b), std::max(a, b), a < b, f});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.Key() < y.Key();
  });
  DisjointSets face_sets(faces.size());
  std::size_t group = 0;  // first half-edge of the current undirected edge
  for (std::size_t i = 1; i <= edges.size() && !edges.empty(); ++i) {
    if (i < edges.size() && edges[i].lo == edges[group].lo && edges[i].hi == edges[group].hi) {
      face_sets.Union(edges[group].face, edges[i].face);
      continue;
    }
    const std::size_t uses = i - group;
    if (uses == 1) ++t.num_boundary_edges;
    if (uses > 2) ++t.num_non_manifold_edges;
    if (uses == 2 && edges[group].forward == edges[group + 1].forward) t.consistent = false;
    // A directed edge is paired when it is the only one of its direction and its opposite the
    // only one of the other; a loop (a, a) is its own opposite.
    const auto forward = std::count_if(edges.begin() + static_cast<std::ptrdiff_t>(group),
                                       edges.begin() + static_cast<std::ptrdiff_t>(i),
                                       [](const HalfEdge& e) { return e.forward; });
    const bool paired =
        edges[group].lo == edges[group].hi ? uses == 1 : uses == 2 && forward == 1;
    if (!paired) t.num_unpaired_half_edges += uses;
    group = i;
  }
  t.num_components = face_sets.CountRoots(faces.size());
}

/// Number of vertices whose corners form more than one fan: corners around a vertex are linked
/// when they share an edge to a neighbour x.
std::size_t CountNonManifoldVertices(const FaceList& faces) {
  struct Corner {
    std::size_t vertex, neighbour, corner;
  };
  std::vector<Corner> links;
  std::size_t num_corners = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto face = faces[f];
    for (std::size_t k = 0; k < face.size(); ++k, ++num_corners) {
      const std::size_t prev = face[(k + face.size() - 1) % face.size()];
      const std::size_t next = face[(k + 1) % face.size()];
      links.push_back({face[k], prev, num_corners});
      links.push_back({face[k], next, num_corners});
    }
  }
  std::sort(links.begin(), links.end(), [](const Corner& x, const Corner& y) {
    return std::tie(x.vertex, x.neighbour, x.corner) < std::tie(y.vertex, y.neighbour, y.corner);
  });
  DisjointSets corner_sets(num_corners);
  for (std::size_t i = 0; i + 1 < links.size(); ++i) {
    if (links[i].vertex == links[i + 1].vertex && links[i].neighbour == links[i + 1].neighbour) {
      corner_sets.Union(links[i].corner, links[i + 1].corner);
    }
  }
  std::size_t non_manifold = 0;
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < links.size();) {
    std::size_t j = i;
    roots.clear();
    while (j < links.size() && links[j].vertex == links[i].vertex) {
      roots.push_back(corner_sets.Find(links[j].corner));
      ++j;
    }
    std::sort(roots.begin(), roots.end());
    const auto fans = std::unique(roots.begin(), roots.end()) - roots.begin();
    if (fans > 1) ++non_manifold;
    i = j;
  }
  return non_manifold;
}

}  // namespace

MeshTopology ComputeMeshTopology(std::span<const Vec3> vertices,
                                 std::span<const std::uint32_t> offsets,
                                 std::span<const std::uint32_t> indices) {
  for (const std::uint32_t v : indices) LINESURF_ASSERT(v < vertices.size());
  const FaceList faces(offsets, indices);
  MeshTopology t;
  CheckEdges(faces, t);
  t.num_non_manifold_vertices = CountNonManifoldVertices(faces);
  t.paired = faces.size() > 0 && t.num_unpaired_half_edges == 0;
  t.signed_volume = SignedVolume(vertices, faces);
  return t;
}

MeshTopology ComputeMeshTopology(const PolygonMesh& mesh) {
  return ComputeMeshTopology(mesh.vertices, mesh.face_offsets, mesh.face_indices);
}

}  // namespace linesurf::pipeline
