#include "engine/pipeline/extract_surface.h"

#include "engine/core/exception.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace linesurf::pipeline {
namespace {

constexpr const char* kStage = "extract_surface";
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
/// A face corner counts as straight (a vertex of a neighbouring facet lying on the side) when
/// |sin(angle)| is under this; only used to pick a triangulation that has no degenerate triangle.
constexpr double kStraightCornerSine = 1e-9;

/// The surface facets with their output cycles (oriented from full to empty).
struct SurfaceFaces {
  std::vector<FacetId> facet;                ///< complex facet of surface face s
  std::vector<std::uint32_t> offsets{0};     ///< corners of face s: [offsets[s], offsets[s+1])
  std::vector<VertexId> corner_vertex;       ///< vertex of each corner
  std::vector<EdgeId> corner_edge;           ///< edge from corner k to corner k+1 of the face
  std::vector<std::uint32_t> partner;        ///< face across corner_edge (joined by a full run)
  std::vector<std::uint32_t> face_of_facet;  ///< surface face of a complex facet, or kNone
};

class Labeler {
 public:
  Labeler(std::span<const std::uint8_t> labels, bool outside_full)
      : labels_(labels), outside_full_(outside_full) {}
  [[nodiscard]] bool Full(CellId c) const {
    return c.IsValid() ? labels_[c.index()] != 0 : outside_full_;
  }

 private:
  std::span<const std::uint8_t> labels_;
  bool outside_full_;
};

SurfaceFaces CollectSurfaceFaces(const CellComplex& cx, const Labeler& label) {
  SurfaceFaces s;
  s.face_of_facet.assign(cx.NumFacets(), kNone);
  for (std::size_t fi = 0; fi < cx.NumFacets(); ++fi) {
    const FacetId f(fi);
    const bool pos_full = label.Full(cx.facet_positive_cell[f]);
    const bool neg_full = label.Full(cx.facet_negative_cell[f]);
    if (pos_full == neg_full) continue;
    const auto verts = cx.facet_vertices[f];
    const auto edges = cx.facet_edges[f];
    LINESURF_ASSERT(verts.size() >= 3 && verts.size() == edges.size());
    s.face_of_facet[fi] = static_cast<std::uint32_t>(s.facet.size());
    s.facet.push_back(f);
    const std::size_t n = verts.size();
    // The stored cycle is counter-clockwise seen from the positive side, so its normal points to
    // the positive cell: keep it when that cell is the empty one, reverse it otherwise.
    for (std::size_t k = 0; k < n; ++k) {
      if (!pos_full) {
        s.corner_vertex.push_back(verts[k]);
        s.corner_edge.push_back(edges[k]);
      } else {
        // Reversed: corner k is vertex n-1-k; the edge from it to vertex n-2-k is edge n-2-k.
        s.corner_vertex.push_back(verts[n - 1 - k]);
        s.corner_edge.push_back(edges[(2 * n - 2 - k) % n]);
      }
    }
    s.offsets.push_back(static_cast<std::uint32_t>(s.corner_vertex.size()));
  }
  s.partner.assign(s.corner_vertex.size(), kNone);
  return s;
}

/// Corner index of edge `e` in face `face` (the corner the edge leaves from).
std::uint32_t EdgeSlot(const SurfaceFaces& s, std::uint32_t face, EdgeId e) {
  for (std::uint32_t k = s.offsets[face]; k < s.offsets[face + 1]; ++k) {
    if (s.corner_edge[k] == e) return k;
  }
  LINESURF_ASSERT(false && "surface facet does not hold its edge");
  return kNone;
}

/// Two surface faces joined across a complex edge.
struct EdgePair {
  EdgeId edge;
  std::uint32_t a;
  std::uint32_t b;
};

/// Around every edge, joins the two surface facets that bound each maximal run of full cells.
/// Appends the pairs of edges with more than two surface facets to `crowded`.
std::size_t PairFacetsAroundEdges(const CellComplex& cx,
                                  const Labeler& label,
                                  SurfaceFaces& s,
                                  std::vector<EdgePair>& crowded) {
  std::size_t non_manifold = 0;
  std::vector<std::uint8_t> full;
  for (std::size_t ei = 0; ei < cx.NumEdges(); ++ei) {
    const EdgeId e(ei);
    const auto facets = cx.edge_facets[e];
    const auto cells = cx.edge_cells[e];
    const std::size_t k = facets.size();
    LINESURF_ASSERT(cells.size() == k || cells.size() + 1 == k);
    // Cell i lies between facets i and i+1; an open chain (box boundary) closes outside the box.
    full.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      full[i] = label.Full(i < cells.size() ? cells[i] : CellId::Invalid()) ? 1 : 0;
    }
    std::size_t surface_here = 0;
    for (std::size_t i = 0; i < k; ++i) {
      const bool on_surface = full[(i + k - 1) % k] != full[i];
      const bool flagged = s.face_of_facet[facets[i].index()] != kNone;
      LINESURF_ASSERT(on_surface == flagged);
      surface_here += on_surface ? 1 : 0;
    }
    if (surface_here == 0) continue;
    if (surface_here > 2) ++non_manifold;
    for (std::size_t i = 0; i < k; ++i) {
      if (!(full[i] != 0 && full[(i + k - 1) % k] == 0)) continue;  // facet i starts a full run
      std::size_t j = i;
      while (full[(j + 1) % k] != 0) j = (j + 1) % k;
      const std::uint32_t a = s.face_of_facet[facets[i].index()];
      const std::uint32_t b = s.face_of_facet[facets[(j + 1) % k].index()];
      LINESURF_ASSERT(a != kNone && b != kNone && a != b);
      s.partner[EdgeSlot(s, a, e)] = b;
      s.partner[EdgeSlot(s, b, e)] = a;
      if (surface_here > 2) crowded.push_back({e, a, b});
    }
  }
  return non_manifold;
}

/// Assigns an output vertex to every corner, one per umbrella of each complex vertex.
std::vector<std::uint32_t> AssignCornerVertices(const CellComplex& cx,
                                                const SurfaceFaces& s,
                                                std::vector<VertexId>& vertex_source) {
  const std::size_t num_corners = s.corner_vertex.size();
  std::vector<std::uint32_t> face_of_corner(num_corners);
  for (std::size_t f = 0; f + 1 < s.offsets.size(); ++f) {
    for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) {
      face_of_corner[k] = static_cast<std::uint32_t>(f);
    }
  }
  // Corners grouped by complex vertex (counting sort keeps corner order within a vertex).
  std::vector<std::uint32_t> vertex_offsets(cx.NumVertices() + 1, 0);
  for (const VertexId v : s.corner_vertex) ++vertex_offsets[v.index() + 1];
  for (std::size_t v = 0; v < cx.NumVertices(); ++v) vertex_offsets[v + 1] += vertex_offsets[v];
  std::vector<std::uint32_t> by_vertex(num_corners);
  {
    std::vector<std::uint32_t> fill(vertex_offsets.begin(), vertex_offsets.end() - 1);
    for (std::uint32_t c = 0; c < num_corners; ++c) {
      by_vertex[fill[s.corner_vertex[c].index()]++] = c;
    }
  }
  const auto next_in_face = [&](std::uint32_t c) {
    const std::uint32_t f = face_of_corner[c];
    return c + 1 < s.offsets[f + 1] ? c + 1 : s.offsets[f];
  };
  std::vector<std::uint32_t> corner_out(num_corners, kNone);
  for (std::size_t v = 0; v < cx.NumVertices(); ++v) {
    for (std::uint32_t idx = vertex_offsets[v]; idx < vertex_offsets[v + 1]; ++idx) {
      const std::uint32_t start = by_vertex[idx];
      if (corner_out[start] != kNone) continue;
      // Walk: leave the corner through its outgoing edge, enter the partner face, whose edge is
      // incoming to this vertex; its next corner is this vertex again.
      const auto id = static_cast<std::uint32_t>(vertex_source.size());
      vertex_source.push_back(VertexId(v));
      std::uint32_t c = start;
      std::size_t steps = 0;
      do {
        LINESURF_ASSERT(s.corner_vertex[c].index() == v && ++steps <= num_corners);
        corner_out[c] = id;
        const std::uint32_t g = s.partner[c];
        LINESURF_ASSERT(g != kNone);
        c = next_in_face(EdgeSlot(s, g, s.corner_edge[c]));
      } while (c != start);
    }
  }
  return corner_out;
}

/// Where both ends of an edge kept a single umbrella, several face pairs of that edge would
/// share one output edge: each of those pairs gets its own vertex at the edge midpoint, inserted
/// in both of its faces. Every pair, the first too, so that all faces along the edge have a
/// corner there: a midpoint in some pairs only would lie on the straight edge of the others (a
/// T-junction, which self-intersection checks rightly report). Returns the vertex inserted
/// after each corner (or kNone).
std::vector<std::uint32_t> SeparateSharedEdges(const CellComplex& cx,
                                               const SurfaceFaces& s,
                                               const std::vector<EdgePair>& crowded,
                                               const std::vector<std::uint32_t>& corner_out,
                                               std::vector<VertexId>& vertex_source,
                                               std::vector<Vec3>& extra_points) {
  std::vector<std::uint32_t> inserted(s.corner_vertex.size(), kNone);
  const auto next_corner = [&](std::uint32_t face, std::uint32_t k) {
    return k + 1 < s.offsets[face + 1] ? k + 1 : s.offsets[face];
  };
  /// A pair of the current edge: its two slots and the output vertices of the edge's ends.
  struct PairEnds {
    std::uint32_t slot_a;
    std::uint32_t slot_b;
    std::pair<std::uint32_t, std::uint32_t> ends;
  };
  std::vector<PairEnds> pairs;
  for (std::size_t i = 0; i < crowded.size();) {
    std::size_t j = i;
    pairs.clear();
    for (; j < crowded.size() && crowded[j].edge == crowded[i].edge; ++j) {
      const EdgePair& p = crowded[j];
      const std::uint32_t ka = EdgeSlot(s, p.a, p.edge);
      const std::uint32_t kb = EdgeSlot(s, p.b, p.edge);
      std::uint32_t x = corner_out[ka];
      std::uint32_t y = corner_out[next_corner(p.a, ka)];
      if (x > y) std::swap(x, y);
      pairs.push_back({ka, kb, {x, y}});
    }
    const auto& ev = cx.edge_vertices[crowded[i].edge];
    const Vec3 midpoint = 0.5 * (cx.vertex_points[ev[0]] + cx.vertex_points[ev[1]]);
    for (const PairEnds& p : pairs) {
      const auto shares_ends = [&](const PairEnds& q) { return &q != &p && q.ends == p.ends; };
      if (std::none_of(pairs.begin(), pairs.end(), shares_ends)) continue;
      const auto id = static_cast<std::uint32_t>(vertex_source.size());
      vertex_source.push_back(VertexId::Invalid());
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

}  // namespace

Expected<ExtractResult> ExtractSurface(const CellComplex& cx,
                                       std::span<const std::uint8_t> labels,
                                       const ExtractOptions& options) noexcept {
  return CatchAll(kStage, [&]() -> ExtractResult {
    LINESURF_THROW_IF(
        labels.size() != cx.NumCells(),
        kInvalidInput,
        kStage,
        "labels has " << labels.size() << " entries for " << cx.NumCells() << " cells");
    const Labeler label(labels, options.outside_full);
    SurfaceFaces s = CollectSurfaceFaces(cx, label);
    ExtractResult result;
    result.stats.surface_facets = s.facet.size();
    std::vector<EdgePair> crowded;
    result.stats.non_manifold_edges = PairFacetsAroundEdges(cx, label, s, crowded);
    const std::vector<std::uint32_t> corner_out = AssignCornerVertices(cx, s, result.vertex_source);
    const std::size_t num_umbrellas = result.vertex_source.size();
    std::vector<Vec3> midpoints;
    const std::vector<std::uint32_t> inserted =
        SeparateSharedEdges(cx, s, crowded, corner_out, result.vertex_source, midpoints);

    std::size_t used_vertices = 0;
    {
      std::vector<std::uint8_t> used(cx.NumVertices(), 0);
      for (std::size_t i = 0; i < num_umbrellas; ++i) used[result.vertex_source[i].index()] = 1;
      for (const std::uint8_t u : used) used_vertices += u;
    }
    result.stats.split_vertices = num_umbrellas - used_vertices + midpoints.size();

    PolygonMesh& mesh = result.mesh;
    mesh.vertices.reserve(result.vertex_source.size());
    for (std::size_t i = 0; i < num_umbrellas; ++i) {
      mesh.vertices.push_back(cx.vertex_points[result.vertex_source[i]]);
    }
    mesh.vertices.insert(mesh.vertices.end(), midpoints.begin(), midpoints.end());
    std::vector<std::uint32_t> face;
    for (std::size_t f = 0; f < s.facet.size(); ++f) {
      face.clear();
      for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) {
        face.push_back(corner_out[k]);
        if (inserted[k] != kNone) face.push_back(inserted[k]);
      }
      const std::size_t n = face.size();
      if (!options.triangulate || n == 3) {
        mesh.AddFace(face);
        result.face_facet.push_back(s.facet[f]);
        continue;
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
          result.face_facet.push_back(s.facet[f]);
        }
        continue;
      }
      Vec3 centroid = Vec3::Zero();
      for (const std::uint32_t v : face) centroid += mesh.vertices[v];
      centroid /= static_cast<double>(n);
      const auto c = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(centroid);
      result.vertex_source.push_back(VertexId::Invalid());
      for (std::size_t k = 0; k < n; ++k) {
        mesh.AddFace(std::array<std::uint32_t, 3>{c, face[k], face[(k + 1) % n]});
        result.face_facet.push_back(s.facet[f]);
      }
    }
    return result;
  });
}

}  // namespace linesurf::pipeline
