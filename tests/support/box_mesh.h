#pragma once
// Axis-aligned box meshes for tests: quads counter-clockwise seen from outside, and the small
// edits tests make to them.

#include "engine/core/polygon_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace linesurf::testing {

/// Axis-aligned box mesh, quads counter-clockwise seen from outside.
inline PolygonMesh Box(const Vec3& lo, const Vec3& hi) {
  PolygonMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                               (i & 4) ? hi.z() : lo.z());
  }
  const std::array<std::array<std::uint32_t, 4>, 6> faces{{
      {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : faces) mesh.AddFace(f);
  return mesh;
}

inline PolygonMesh Cube(double half) { return Box(Vec3::Constant(-half), Vec3::Constant(half)); }

inline PolygonMesh Append(PolygonMesh a, const PolygonMesh& b) {
  const auto base = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (std::size_t f = 0; f < b.NumFaces(); ++f) {
    std::vector<std::uint32_t> face(b.Face(f).begin(), b.Face(f).end());
    for (auto& v : face) v += base;
    a.AddFace(face);
  }
  return a;
}

/// Merges vertices at identical positions (simple O(V^2)).
inline PolygonMesh Weld(PolygonMesh mesh) {
  std::vector<std::uint32_t> target(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    target[v] = static_cast<std::uint32_t>(v);
    for (std::size_t u = 0; u < v; ++u) {
      if (mesh.vertices[u] == mesh.vertices[v]) {
        target[v] = target[u];
        break;
      }
    }
  }
  for (auto& i : mesh.face_indices) i = target[i];
  return mesh;
}

}  // namespace linesurf::testing
