#include "engine/core/face_triangulation.h"

#include "engine/core/vector_area.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>

namespace linesurf {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// Turn of the corner a-b-c about `normal`: > 0 convex, < 0 reflex, 0 straight. Turns smaller
/// than a relative 1e-9 of the two edges count as straight, so rounding does not make a straight
/// corner reflex (a convex face keeps its fan).
int Turn(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  const Vec3 u = b - a;
  const Vec3 v = c - b;
  const double turn = u.cross(v).dot(normal);
  const double scale = u.norm() * v.norm() * normal.norm();
  if (std::abs(turn) <= 1e-9 * scale) return 0;
  return turn > 0.0 ? 1 : -1;
}

/// Whether p lies in the closed triangle a-b-c (counter-clockwise about `normal`).
bool InTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  return Turn(a, b, p, normal) >= 0 && Turn(b, c, p, normal) >= 0 && Turn(c, a, p, normal) >= 0;
}

void Fan(std::span<const std::uint32_t> ring, Triangles& out) {
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) out.push_back({ring[0], ring[k], ring[k + 1]});
}

}  // namespace

Triangles FaceTriangles(std::span<const Vec3> vertices, std::span<const std::uint32_t> face) {
  Triangles out;
  if (face.size() < 3) return out;
  const Vec3 normal = TwiceVectorArea(vertices, face);
  const std::size_t n = face.size();
  const auto turn_at = [&](std::span<const std::uint32_t> ring, std::size_t k) {
    const std::size_t m = ring.size();
    return Turn(
        vertices[ring[(k + m - 1) % m]], vertices[ring[k]], vertices[ring[(k + 1) % m]], normal);
  };
  bool reflex = false;
  for (std::size_t k = 0; k < n && !reflex; ++k) reflex = turn_at(face, k) < 0;
  if (!reflex) {
    Fan(face, out);
    return out;
  }
  std::vector<std::uint32_t> ring(face.begin(), face.end());
  out.reserve(n - 2);
  while (ring.size() > 3) {
    const std::size_t m = ring.size();
    bool clipped = false;
    for (std::size_t k = 0; k < m && !clipped; ++k) {
      const int turn = turn_at(ring, k);
      if (turn < 0) continue;
      const std::uint32_t prev = ring[(k + m - 1) % m];
      const std::uint32_t next = ring[(k + 1) % m];
      // A convex corner is an ear when no other corner lies in its triangle; a straight corner
      // goes as a degenerate triangle whenever met.
      bool ear = true;
      for (std::size_t j = 0; j < m && ear && turn > 0; ++j) {
        const std::uint32_t q = ring[j];
        if (q == prev || q == ring[k] || q == next) continue;
        const Vec3& p = vertices[q];
        if (p == vertices[prev] || p == vertices[ring[k]] || p == vertices[next]) continue;
        ear = !InTriangle(p, vertices[prev], vertices[ring[k]], vertices[next], normal);
      }
      if (!ear) continue;
      out.push_back({prev, ring[k], next});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) break;  // not a simple polygon: fan what is left
  }
  Fan(ring, out);
  return out;
}

}  // namespace linesurf
