#include "engine/pipeline/mesh_index_topology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace linesurf::pipeline {

IndexTopology CheckIndexTopology(const PolygonMesh& mesh) {
  IndexTopology t;
  const std::size_t nv = mesh.vertices.size();
  using Directed = std::array<std::uint32_t, 2>;
  std::vector<Directed> edges;
  edges.reserve(mesh.face_indices.size());
  bool in_range = true;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::uint32_t a = face[k];
      const std::uint32_t b = face[(k + 1) % face.size()];
      if (a >= nv || b >= nv) {
        in_range = false;
        continue;
      }
      edges.push_back({a, b});
    }
    if (face.size() >= 3 && in_range) {
      const Vec3& p0 = mesh.vertices[face[0]];
      for (std::size_t k = 1; k + 1 < face.size(); ++k) {
        t.signed_volume +=
            p0.dot(mesh.vertices[face[k]].cross(mesh.vertices[face[k + 1]])) / 6.0;
      }
    }
  }
  if (!in_range) return t;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const bool repeated = (i > 0 && edges[i - 1] == edges[i]) ||
                          (i + 1 < edges.size() && edges[i + 1] == edges[i]);
    const Directed opposite{edges[i][1], edges[i][0]};
    const auto range = std::equal_range(edges.begin(), edges.end(), opposite);
    if (repeated || range.second - range.first != 1) ++t.boundary_or_repeated_edges;
  }
  t.closed = mesh.NumFaces() > 0 && t.boundary_or_repeated_edges == 0;
  if (!t.closed) return t;
  // Fans: at vertex v every face corner maps its incoming neighbour to its outgoing one; a single
  // fan is a single cycle of that map.
  std::vector<std::array<std::uint32_t, 3>> corners;  // (v, prev, next)
  corners.reserve(mesh.face_indices.size());
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    const std::size_t n = face.size();
    for (std::size_t k = 0; k < n; ++k) {
      corners.push_back({face[k], face[(k + n - 1) % n], face[(k + 1) % n]});
    }
  }
  std::sort(corners.begin(), corners.end());
  for (std::size_t i = 0; i < corners.size();) {
    std::size_t j = i;
    while (j < corners.size() && corners[j][0] == corners[i][0]) ++j;
    // Follow next -> the corner whose prev is that vertex, from corners[i].
    std::size_t steps = 0;
    std::uint32_t next = corners[i][2];
    const std::uint32_t first_prev = corners[i][1];
    while (steps < j - i) {
      ++steps;
      if (next == first_prev) break;
      const auto it = std::find_if(corners.begin() + static_cast<std::ptrdiff_t>(i),
                                   corners.begin() + static_cast<std::ptrdiff_t>(j),
                                   [&](const auto& c) { return c[1] == next; });
      if (it == corners.begin() + static_cast<std::ptrdiff_t>(j)) break;
      next = (*it)[2];
    }
    if (steps != j - i) ++t.non_manifold_vertices;
    i = j;
  }
  t.manifold = t.non_manifold_vertices == 0;
  return t;
}

}  // namespace linesurf::pipeline
