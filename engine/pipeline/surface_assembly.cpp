#include "engine/pipeline/surface_assembly.h"

#include "engine/core/csr.h"
#include "engine/core/exception.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <utility>

namespace linesurf::pipeline {
namespace {

/// A face corner counts as straight (a vertex of a neighbouring facet lying on the side) when
/// |sin(angle)| is under this; only used to pick a triangulation that has no degenerate triangle.
constexpr double kStraightCornerSine = 1e-9;

/// Assigns an output vertex to every corner, one per umbrella of each candidate vertex.
std::vector<MeshVertexId> AssignCornerVertices(std::size_t num_vertices,
                                               const SurfaceCycles& s,
                                               std::vector<CandidateVertexId>& vertex_source) {
  const std::size_t num_corners = s.corner_vertex.size();
  // Corners grouped by vertex, in corner order within a vertex.
  for (const std::uint32_t v : s.corner_vertex) LINESURF_ASSERT(v < num_vertices);
  const auto by_vertex = Csr<std::uint32_t, std::uint32_t>::FromPairs(
      num_vertices,
      num_corners,
      [&](std::size_t c) { return s.corner_vertex[c]; },
      [](std::size_t c) { return static_cast<std::uint32_t>(c); });
  std::vector<MeshVertexId> corner_out(num_corners);
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    for (const std::uint32_t start : by_vertex[v]) {
      if (corner_out[start].IsValid()) continue;
      // Walk: leave the corner through its outgoing edge, enter the partner face, whose edge is
      // incoming to this vertex; its next corner is this vertex again.
      const MeshVertexId id(vertex_source.size());
      vertex_source.emplace_back(v);
      std::uint32_t c = start;
      std::size_t steps = 0;
      do {
        LINESURF_ASSERT(s.corner_vertex[c] == v && ++steps <= num_corners);
        corner_out[c] = id;
        const SurfaceFaceId g = s.partner[c];
        LINESURF_ASSERT(g.IsValid());
        c = s.NextCorner(g, s.EdgeSlot(g, s.corner_edge[c]));
      } while (c != start);
    }
  }
  return corner_out;
}

/// Where both ends of an edge kept a single umbrella, several face pairs of that edge would
/// share one output edge: then every pair of the edge gets its own vertex at the edge midpoint,
/// inserted in both of its faces. Every pair, the first too and those whose ends are other
/// umbrellas at the same points, so that all faces along the edge have a corner there: a
/// midpoint in some pairs only would lie on the straight edge of the others (a T-junction, which
/// self-intersection checks rightly report). Returns the vertex inserted after each corner (or
/// an invalid id).
std::vector<MeshVertexId> SeparateSharedEdges(const SurfaceCycles& s,
                                              std::span<const Vec3> points,
                                              std::span<const EdgePair> crowded,
                                              const std::vector<MeshVertexId>& corner_out,
                                              std::vector<CandidateVertexId>& vertex_source,
                                              std::vector<Vec3>& extra_points) {
  std::vector<MeshVertexId> inserted(s.corner_vertex.size());
  /// A pair of the current edge: its two slots and the output vertices of the edge's ends.
  struct PairEnds {
    std::uint32_t slot_a;
    std::uint32_t slot_b;
    std::pair<MeshVertexId, MeshVertexId> ends;
  };
  std::vector<PairEnds> pairs;
  for (std::size_t i = 0; i < crowded.size();) {
    std::size_t j = i;
    pairs.clear();
    for (; j < crowded.size() && crowded[j].edge == crowded[i].edge; ++j) {
      const EdgePair& p = crowded[j];
      const std::uint32_t ka = s.EdgeSlot(p.a, p.edge);
      const std::uint32_t kb = s.EdgeSlot(p.b, p.edge);
      MeshVertexId x = corner_out[ka];
      MeshVertexId y = corner_out[s.NextCorner(p.a, ka)];
      if (x > y) std::swap(x, y);
      pairs.push_back({ka, kb, {x, y}});
    }
    const std::uint32_t k0 = pairs.front().slot_a;
    const Vec3 midpoint = 0.5 * (points[s.corner_vertex[k0]] +
                                 points[s.corner_vertex[s.NextCorner(crowded[i].a, k0)]]);
    const bool shared = std::any_of(pairs.begin(), pairs.end(), [&](const PairEnds& p) {
      return std::any_of(pairs.begin(), pairs.end(), [&](const PairEnds& q) {
        return &q != &p && q.ends == p.ends;
      });
    });
    for (const PairEnds& p :
         shared ? std::span<const PairEnds>(pairs) : std::span<const PairEnds>()) {
      const MeshVertexId id(vertex_source.size());
      vertex_source.push_back(CandidateVertexId::Invalid());
      extra_points.push_back(midpoint);
      inserted[p.slot_a] = id;
      inserted[p.slot_b] = id;
    }
    i = j;
  }
  return inserted;
}

bool IsStraightCorner(const Vec3& prev, const Vec3& p, const Vec3& next) {
  const Vec3 a = prev - p;
  const Vec3 b = next - p;
  return a.cross(b).norm() <= kStraightCornerSine * a.norm() * b.norm();
}

/// Appends face `face` (output vertex ids), as it is or as triangles.
void AddOutputFace(const std::vector<std::uint32_t>& face,
                   std::uint32_t cycle,
                   bool triangulate,
                   AssembledSurface& out) {
  PolygonMesh& mesh = out.mesh;
  const std::size_t n = face.size();
  if (!triangulate || n == 3) {
    mesh.AddFace(face);
    out.face_cycle.push_back(cycle);
    return;
  }
  bool straight = false;
  for (std::size_t k = 0; k < n && !straight; ++k) {
    straight = IsStraightCorner(mesh.vertices[face[(k + n - 1) % n]],
                                mesh.vertices[face[k]],
                                mesh.vertices[face[(k + 1) % n]]);
  }
  if (!straight) {
    for (std::size_t k = 1; k + 1 < n; ++k) {
      mesh.AddFace(std::array<std::uint32_t, 3>{face[0], face[k], face[k + 1]});
      out.face_cycle.push_back(cycle);
    }
    return;
  }
  Vec3 centroid = Vec3::Zero();
  for (const std::uint32_t v : face) centroid += mesh.vertices[v];
  centroid /= static_cast<double>(n);
  const auto c = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(centroid);
  out.vertex_source.push_back(CandidateVertexId::Invalid());
  for (std::size_t k = 0; k < n; ++k) {
    mesh.AddFace(std::array<std::uint32_t, 3>{c, face[k], face[(k + 1) % n]});
    out.face_cycle.push_back(cycle);
  }
}

}  // namespace

void SurfaceCycles::AddCycle(std::span<const std::uint32_t> vertices,
                             std::span<const std::uint32_t> edges,
                             bool reverse) {
  const std::size_t n = vertices.size();
  LINESURF_ASSERT(n >= 3 && edges.size() == n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!reverse) {
      corner_vertex.push_back(vertices[k]);
      corner_edge.emplace_back(edges[k]);
    } else {
      // Reversed: corner k is vertex n-1-k; the edge from it to vertex n-2-k is edge n-2-k.
      corner_vertex.push_back(vertices[n - 1 - k]);
      corner_edge.emplace_back(edges[(2 * n - 2 - k) % n]);
    }
    partner.push_back(SurfaceFaceId::Invalid());
  }
  offsets.push_back(static_cast<std::uint32_t>(corner_vertex.size()));
}

std::uint32_t SurfaceCycles::EdgeSlot(SurfaceFaceId face, SurfaceEdgeId edge) const {
  const std::uint32_t end = offsets[face.index() + 1];
  std::uint32_t k = offsets[face.index()];
  while (k < end && corner_edge[k] != edge) ++k;
  LINESURF_ASSERT(k < end && "surface face does not hold its edge");
  return k;
}

std::size_t PairAroundComplexEdges(const CellComplex& cx,
                                   std::span<const std::uint8_t> labels,
                                   bool outside_full,
                                   std::span<const SurfaceFaceId> face_of_facet,
                                   std::uint32_t edge_offset,
                                   std::span<const std::uint8_t> skip_facet,
                                   SurfaceCycles& s,
                                   std::vector<EdgePair>& crowded) {
  const auto full_cell = [&](CellId c) {
    return c.IsValid() ? labels[c.index()] != 0 : outside_full;
  };
  std::size_t non_manifold = 0;
  std::vector<std::uint8_t> full;
  for (std::size_t ei = 0; ei < cx.NumEdges(); ++ei) {
    const EdgeId e(ei);
    const auto facets = cx.edge_facets[e];
    const auto cells = cx.edge_cells[e];
    const std::size_t k = facets.size();
    LINESURF_ASSERT(cells.size() == k || cells.size() + 1 == k);
    if (!skip_facet.empty() && std::any_of(facets.begin(), facets.end(), [&](FacetId f) {
          return skip_facet[f.index()] != 0;
        })) {
      continue;
    }
    // Cell i lies between facets i and i+1; an open chain (box boundary) closes outside the box.
    full.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      full[i] = full_cell(i < cells.size() ? cells[i] : CellId::Invalid()) ? 1 : 0;
    }
    std::size_t surface_here = 0;
    for (std::size_t i = 0; i < k; ++i) {
      const bool on_surface = full[(i + k - 1) % k] != full[i];
      const bool flagged = face_of_facet[facets[i].index()].IsValid();
      LINESURF_ASSERT(on_surface == flagged);
      surface_here += on_surface ? 1 : 0;
    }
    if (surface_here == 0) continue;
    if (surface_here > 2) ++non_manifold;
    const SurfaceEdgeId edge(edge_offset + ei);
    for (std::size_t i = 0; i < k; ++i) {
      if (!(full[i] != 0 && full[(i + k - 1) % k] == 0)) continue;  // facet i starts a full run
      std::size_t j = i;
      while (full[(j + 1) % k] != 0) j = (j + 1) % k;
      const SurfaceFaceId a = face_of_facet[facets[i].index()];
      const SurfaceFaceId b = face_of_facet[facets[(j + 1) % k].index()];
      LINESURF_ASSERT(a.IsValid() && b.IsValid() && a != b);
      s.partner[s.EdgeSlot(a, edge)] = b;
      s.partner[s.EdgeSlot(b, edge)] = a;
      if (surface_here > 2) crowded.push_back({edge, a, b});
    }
  }
  return non_manifold;
}

AssembledSurface AssembleSurface(const SurfaceCycles& s,
                                 std::span<const Vec3> points,
                                 std::span<const EdgePair> crowded,
                                 bool triangulate) {
  AssembledSurface out;
  const std::vector<MeshVertexId> corner_out =
      AssignCornerVertices(points.size(), s, out.vertex_source);
  const std::size_t num_umbrellas = out.vertex_source.size();
  std::vector<Vec3> midpoints;
  const std::vector<MeshVertexId> inserted =
      SeparateSharedEdges(s, points, crowded, corner_out, out.vertex_source, midpoints);

  std::size_t used_vertices = 0;
  {
    std::vector<std::uint8_t> used(points.size(), 0);
    for (std::size_t i = 0; i < num_umbrellas; ++i) used[out.vertex_source[i].index()] = 1;
    for (const std::uint8_t u : used) used_vertices += u;
  }
  out.split_vertices = num_umbrellas - used_vertices + midpoints.size();

  PolygonMesh& mesh = out.mesh;
  mesh.vertices.reserve(out.vertex_source.size());
  for (std::size_t i = 0; i < num_umbrellas; ++i)
    mesh.vertices.push_back(points[out.vertex_source[i].index()]);
  mesh.vertices.insert(mesh.vertices.end(), midpoints.begin(), midpoints.end());
  std::vector<std::uint32_t> face;
  for (std::size_t f = 0; f < s.NumFaces(); ++f) {
    face.clear();
    for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) {
      face.push_back(corner_out[k].value());
      if (inserted[k].IsValid()) face.push_back(inserted[k].value());
    }
    AddOutputFace(face, static_cast<std::uint32_t>(f), triangulate, out);
  }
  return out;
}

}  // namespace linesurf::pipeline
