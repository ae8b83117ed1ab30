#include "engine/io/planar_polygons.h"

#include "engine/core/disjoint_sets.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace linesurf::io {
namespace {

using Vec2 = Eigen::Vector2d;

struct DirectedEdge {
  std::uint32_t from;
  std::uint32_t to;
  std::uint32_t face;  ///< position in the group's face list
  auto operator<=>(const DirectedEdge&) const = default;
};

/// Coordinates in the plane, counter-clockwise about `normal` (u x v = normal).
struct PlaneFrame {
  Vec3 u;
  Vec3 v;
  explicit PlaneFrame(const Vec3& normal) {
    const Vec3 n = normal.normalized();
    const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    u = helper.cross(n).normalized();
    v = n.cross(u);
  }
  [[nodiscard]] Vec2 Of(const Vec3& p, const Vec3& origin) const {
    const Vec3 d = p - origin;
    return {d.dot(u), d.dot(v)};
  }
};

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Twice the signed area of `ring` in `frame` (about its first corner, for precision).
double TwiceSignedArea(const std::vector<Vec2>& ring) {
  double sum = 0.0;
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
    sum += Cross(ring[k] - ring[0], ring[k + 1] - ring[0]);
  }
  return sum;
}

/// Even-odd test of `p` against `ring`.
bool Inside(const Vec2& p, const std::vector<Vec2>& ring) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

/// The rings of one edge-connected group, outer ring first, or nothing when the boundary does
/// not trace into one counter-clockwise ring and clockwise rings inside it.
std::optional<PlanarPolygon> TraceGroup(const PolygonMesh& mesh,
                                        std::span<const DirectedEdge> boundary,
                                        const PlaneFrame& frame) {
  const Vec3 origin = mesh.vertices[boundary.front().from];
  auto at = [&](std::uint32_t vertex) { return frame.Of(mesh.vertices[vertex], origin); };
  // Boundary edges sorted by tail; next(e) is the outgoing edge at e's head that turns
  // clockwise most from the way back: where the region meets itself at a vertex (a hole
  // touching the outer boundary), the rings cross over there instead of passing it twice.
  std::vector<DirectedEdge> by_tail(boundary.begin(), boundary.end());
  std::sort(by_tail.begin(), by_tail.end());
  auto outgoing = [&](std::uint32_t vertex) {
    const auto first = std::lower_bound(
        by_tail.begin(), by_tail.end(), vertex, [](const DirectedEdge& e, std::uint32_t x) {
          return e.from < x;
        });
    auto last = first;
    while (last != by_tail.end() && last->from == vertex) ++last;
    return std::pair{first, last};
  };
  std::vector<bool> used(by_tail.size(), false);
  std::vector<std::vector<std::uint32_t>> rings;
  std::vector<std::vector<Vec2>> rings_2d;
  for (std::size_t start = 0; start < by_tail.size(); ++start) {
    if (used[start]) continue;
    std::vector<std::uint32_t> ring;
    std::size_t current = start;
    while (true) {
      if (used[current]) {
        if (current != start) return std::nullopt;  // two rings claim one edge
        break;
      }
      used[current] = true;
      const DirectedEdge& e = by_tail[current];
      ring.push_back(e.from);
      const Vec2 back = at(e.from) - at(e.to);
      const auto [first, last] = outgoing(e.to);
      if (first == last) return std::nullopt;  // an open chain
      double best_turn = -1.0;
      for (auto it = first; it != last; ++it) {
        const Vec2 out = at(it->to) - at(e.to);
        double turn = -std::atan2(Cross(back, out), back.dot(out));
        if (turn <= 0.0) turn += 2.0 * M_PI;
        if (turn > best_turn) {
          best_turn = turn;
          current = static_cast<std::size_t>(it - by_tail.begin());
        }
      }
    }
    std::vector<Vec2> ring_2d;
    ring_2d.reserve(ring.size());
    for (const std::uint32_t vertex : ring) ring_2d.push_back(at(vertex));
    std::vector<std::uint32_t> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (ring.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      return std::nullopt;  // a ring through one vertex twice
    }
    rings.push_back(std::move(ring));
    rings_2d.push_back(std::move(ring_2d));
  }
  // One counter-clockwise ring; every clockwise one is a hole inside it.
  std::optional<std::size_t> outer;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (TwiceSignedArea(rings_2d[r]) <= 0.0) continue;
    if (outer) return std::nullopt;
    outer = r;
  }
  if (!outer) return std::nullopt;
  PlanarPolygon polygon;
  polygon.rings.push_back(rings[*outer]);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (r == *outer) continue;
    const Vec2 probe = 0.5 * (rings_2d[r][0] + rings_2d[r][1]);
    if (!Inside(probe, rings_2d[*outer])) return std::nullopt;
    polygon.rings.push_back(std::move(rings[r]));
  }
  return polygon;
}

}  // namespace

std::vector<PlanarPolygon> JoinIntoPlanarPolygons(const PolygonMesh& mesh,
                                                  std::span<const std::uint32_t> faces,
                                                  const Vec3& normal) {
  std::vector<DirectedEdge> edges;
  for (std::uint32_t k = 0; k < faces.size(); ++k) {
    const auto face = mesh.Face(faces[k]);
    for (std::size_t i = 0; i < face.size(); ++i) {
      edges.push_back({face[i], face[(i + 1) % face.size()], k});
    }
  }
  std::sort(edges.begin(), edges.end());
  // The faces of `from -> to`, as a range of `edges`.
  auto with_ends = [&](std::uint32_t from, std::uint32_t to) {
    return std::equal_range(
        edges.begin(), edges.end(), DirectedEdge{from, to, 0},
        [](const DirectedEdge& a, const DirectedEdge& b) {
          return std::tie(a.from, a.to) < std::tie(b.from, b.to);
        });
  };
  DisjointSets groups(faces.size());
  std::vector<bool> interior(edges.size(), false);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto same = with_ends(edges[i].from, edges[i].to);
    const auto reverse = with_ends(edges[i].to, edges[i].from);
    if (same.second - same.first == 1 && reverse.second - reverse.first == 1) {
      interior[i] = true;
      groups.Union(edges[i].face, reverse.first->face);
    }
  }
  // Boundary edges per group, the groups numbered by their first face.
  std::vector<std::vector<DirectedEdge>> boundary_of(faces.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!interior[i]) boundary_of[groups.Find(edges[i].face)].push_back(edges[i]);
  }
  const PlaneFrame frame(normal);
  std::vector<PlanarPolygon> polygons;
  for (std::uint32_t k = 0; k < faces.size(); ++k) {
    if (groups.Find(k) != k) continue;
    std::optional<PlanarPolygon> joined;
    if (!boundary_of[k].empty()) joined = TraceGroup(mesh, boundary_of[k], frame);
    if (joined) {
      polygons.push_back(std::move(*joined));
      continue;
    }
    for (std::uint32_t member = k; member < faces.size(); ++member) {
      if (groups.Find(member) != k) continue;
      const auto face = mesh.Face(faces[member]);
      polygons.push_back(PlanarPolygon{{std::vector<std::uint32_t>(face.begin(), face.end())}});
    }
  }
  return polygons;
}

}  // namespace linesurf::io
