#include "engine/pipeline/extract_block_surface.h"

#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/pipeline/merge_coplanar_faces.h"
#include "engine/pipeline/surface_assembly.h"
#include "partition/arrangement/vertex_key_geometry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace linesurf::pipeline {
namespace {

using partition::BlockComplex;
using partition::BlockComplexes;
using partition::FacetKind;
using partition::KeySegment;
using partition::PlaneKey;
using partition::SeamFace;
using partition::SeamFacet;
using partition::VertexKey;

constexpr const char* kExtractBlockSurfaceStage = "extract_block_surface";
/// Rounded vertices are within 1e-10 (relative) of the exact point (exact_predicates.cpp); two
/// triples whose rounded points are closer than this (relative to the scene's coordinates) are
/// candidates for one point, decided exactly.
constexpr double kCandidateDistance = 1e-8;
/// Cells of the grid that finds vertices on edges, per base block side.
constexpr double kEdgeSearchCellsPerBlock = 8.0;

/// Where a triple first occurs: (2 * block + 0, vertex id) for a block's own vertices,
/// (2 * block + 1, running number) for corners of the seam facets the block is the lower block of.
using Rank = std::array<std::uint64_t, 2>;

/// A corner of a surface face as collected, before vertices are merged.
struct RawCorner {
  VertexKey key;
  Rank rank;
  Vec3 point;
  /// Global id of the block edge leaving this corner when that edge is off the shared faces (its
  /// star in the block is complete), else invalid and the edge lies on the line of (p, q).
  SurfaceEdgeId edge;
  PlaneKey p;
  PlaneKey q;
};

struct RawFace {
  BlockFacetRef ref;
  PlaneKey plane;              ///< the plane the face lies on
  Vec3 normal = Vec3::Zero();  ///< outward (exact: a plane normal, maybe negated)
  std::uint32_t begin = 0;     ///< corners [begin, end) of the block part, oriented
  std::uint32_t end = 0;
};

/// The surface faces of one block: its own facets, then the seam facets it is the lower block of.
struct BlockPart {
  std::vector<RawFace> faces;
  std::vector<RawCorner> corners;
  std::vector<SurfaceFaceId> face_of_facet;  ///< local face of each facet of the block
  std::vector<std::uint8_t> seam_facet;      ///< facets on shared faces (replaced by the overlay)
};

/// The facet of the same cell as facet f on edge e: its plane carries the edge's line with f's.
FacetId OtherFacetOfCell(const CellComplex& c, FacetId f, EdgeId e) {
  const CellId cell = c.facet_positive_cell[f];
  for (const FacetId g : c.edge_facets[e]) {
    if (g != f && (c.facet_positive_cell[g] == cell || c.facet_negative_cell[g] == cell)) return g;
  }
  LINESURF_THROW_IF(
      true, kInternal, kExtractBlockSurfaceStage, "facet edge without a second facet of its cell");
  return {};
}

/// Corner k of a cycle of n stored counter-clockwise seen from the side its normal points to,
/// reversed when that side is full: the stored vertex and the stored edge leaving it.
std::pair<std::size_t, std::size_t> Oriented(std::size_t k, std::size_t n, bool reverse) {
  if (!reverse) return {k, k};
  return {n - 1 - k, (2 * n - 2 - k) % n};
}

class Collector {
 public:
  Collector(const BlockComplexes& cx,
            std::span<const std::uint8_t> labels,
            const std::vector<std::size_t>& cell_offsets,
            bool outside_full)
      : cx_(cx), labels_(labels), cell_offsets_(cell_offsets), outside_full_(outside_full) {}

  [[nodiscard]] bool Full(std::size_t block, CellId c) const {
    return c.IsValid() ? labels_[cell_offsets_[block] + c.index()] != 0 : outside_full_;
  }

  BlockPart Collect(std::size_t b,
                    std::uint32_t edge_offset,
                    std::span<const SeamFace> lower_seams,
                    std::uint32_t first_seam) const {
    const BlockComplex& block = cx_.blocks[b];
    const CellComplex& c = block.complex;
    BlockPart part;
    part.face_of_facet.assign(c.NumFacets(), SurfaceFaceId::Invalid());
    part.seam_facet.assign(c.NumFacets(), 0);
    for (std::size_t f = 0; f < c.NumFacets(); ++f) {
      part.seam_facet[f] = block.facet_kind[FacetId(f)] == FacetKind::kSeam ? 1 : 0;
    }
    std::vector<std::uint8_t> on_seam(c.NumEdges(), 0);
    for (std::size_t e = 0; e < c.NumEdges(); ++e) {
      for (const FacetId f : c.edge_facets[EdgeId(e)]) on_seam[e] |= part.seam_facet[f.index()];
    }
    for (std::size_t fi = 0; fi < c.NumFacets(); ++fi) {
      const FacetId f(fi);
      if (part.seam_facet[fi] != 0) continue;
      const bool pos_full = Full(b, c.facet_positive_cell[f]);
      if (pos_full == Full(b, c.facet_negative_cell[f])) continue;
      const auto vertices = c.facet_vertices[f];
      const auto edges = c.facet_edges[f];
      const std::size_t plane = c.facet_plane[f].index();
      RawFace face{{false, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(fi)},
                   block.plane_keys[plane],
                   (pos_full ? -1.0 : 1.0) * c.planes[c.facet_plane[f]].coefficients.head<3>(),
                   static_cast<std::uint32_t>(part.corners.size()),
                   0};
      for (std::size_t k = 0; k < vertices.size(); ++k) {
        const auto [iv, ie] = Oriented(k, vertices.size(), pos_full);
        const VertexId v = vertices[iv];
        const EdgeId e = edges[ie];
        RawCorner corner{partition::BlockVertexKey(block, v),
                         {2 * std::uint64_t{b}, v.value()},
                         c.vertex_points[v],
                         SurfaceEdgeId::Invalid(),
                         {},
                         {}};
        if (on_seam[e.index()] == 0) {
          corner.edge = SurfaceEdgeId(edge_offset + e.value());
        } else {
          corner.p = block.plane_keys[plane];
          corner.q = block.plane_keys[c.facet_plane[OtherFacetOfCell(c, f, e)].index()];
        }
        part.corners.push_back(corner);
      }
      face.end = static_cast<std::uint32_t>(part.corners.size());
      part.face_of_facet[fi] = SurfaceFaceId(part.faces.size());
      part.faces.push_back(face);
    }
    std::uint64_t seam_corner = 0;
    for (std::size_t s = 0; s < lower_seams.size(); ++s) {
      const SeamFace& seam = lower_seams[s];
      const PlaneKey key = PlaneKey::Face(seam.axis, block.base[seam.axis] + 1);
      for (std::size_t i = 0; i < seam.facets.size(); ++i) {
        const SeamFacet& facet = seam.facets[i];
        const bool lower_full = Full(seam.lower_block, facet.lower_cell);
        if (lower_full == Full(seam.upper_block, facet.upper_cell)) continue;
        // Stored counter-clockwise seen from the lower block: kept when that side is empty.
        Vec3 normal = Vec3::Zero();
        normal[seam.axis] = lower_full ? 1.0 : -1.0;
        RawFace face{
            {true, first_seam + static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(i)},
            key,
            normal,
            static_cast<std::uint32_t>(part.corners.size()),
            0};
        const std::size_t n = facet.vertices.size();
        for (std::size_t k = 0; k < n; ++k) {
          const auto [iv, ie] = Oriented(k, n, lower_full);
          part.corners.push_back({facet.vertices[iv],
                                  {2 * std::uint64_t{b} + 1, seam_corner++},
                                  facet.points[iv],
                                  SurfaceEdgeId::Invalid(),
                                  key,
                                  facet.edge_planes[ie]});
        }
        face.end = static_cast<std::uint32_t>(part.corners.size());
        part.faces.push_back(face);
      }
    }
    return part;
  }

 private:
  const BlockComplexes& cx_;
  std::span<const std::uint8_t> labels_;
  const std::vector<std::size_t>& cell_offsets_;
  bool outside_full_;
};

using Cell3 = std::array<std::int64_t, 3>;

Cell3 CellOf(const Vec3& p, double h) {
  return {static_cast<std::int64_t>(std::floor(p.x() / h)),
          static_cast<std::int64_t>(std::floor(p.y() / h)),
          static_cast<std::int64_t>(std::floor(p.z() / h))};
}

/// Points hashed into cubes of side h, sorted by cube (deterministic lookups, no hashing order).
class PointGrid {
 public:
  PointGrid(double h, std::vector<std::pair<Cell3, std::uint32_t>> entries)
      : h_(h), entries_(std::move(entries)) {
    std::sort(entries_.begin(), entries_.end());
  }
  /// Calls fn(id) for every point in a cube meeting the box [lo, hi].
  template <typename Fn>
  void ForEachNear(const Vec3& lo, const Vec3& hi, Fn&& fn) const {
    const Cell3 a = CellOf(lo, h_);
    const Cell3 b = CellOf(hi, h_);
    Cell3 c;
    for (c[0] = a[0]; c[0] <= b[0]; ++c[0]) {
      for (c[1] = a[1]; c[1] <= b[1]; ++c[1]) {
        for (c[2] = a[2]; c[2] <= b[2]; ++c[2]) {
          auto it = std::lower_bound(
              entries_.begin(), entries_.end(), std::make_pair(c, std::uint32_t{0}));
          for (; it != entries_.end() && it->first == c; ++it) fn(it->second);
        }
      }
    }
  }

 private:
  double h_;
  std::vector<std::pair<Cell3, std::uint32_t>> entries_;
};

/// A distinct vertex triple among the corners (MergeVertices).
struct DistinctKeyTag {};
using DistinctKeyId = StrongId<DistinctKeyTag>;

/// The vertices of the surface: one per point, whichever triples name it.
struct MergedVertices {
  std::vector<std::uint32_t> of_corner;  ///< vertex of every raw corner (in part order)
  std::vector<VertexKey> keys;           ///< the first-occurring triple of each vertex
  std::vector<Vec3> points;              ///< its rounded point
  std::vector<std::uint8_t> on_face;     ///< on a block face (may lie on another face's edge)
  std::size_t merged_keys = 0;
};

MergedVertices MergeVertices(const BlockComplexes& cx,
                             const std::vector<const RawCorner*>& corners,
                             double distance) {
  std::vector<std::uint32_t> order(corners.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(corners[a]->key, corners[a]->rank) <
           std::tie(corners[b]->key, corners[b]->rank);
  });
  // Distinct triples, each with its first occurrence.
  std::vector<std::uint32_t> first;  // corner of the first occurrence of distinct triple i
  std::vector<std::uint32_t> distinct_of_corner(corners.size());
  for (const std::uint32_t c : order) {
    if (first.empty() || corners[first.back()]->key != corners[c]->key) first.push_back(c);
    distinct_of_corner[c] = static_cast<std::uint32_t>(first.size() - 1);
  }
  const std::size_t n = first.size();
  DisjointSets sets(n);
  std::vector<std::pair<Cell3, std::uint32_t>> entries;
  const double h = 2.0 * distance;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (partition::OnSomeBlockFace(corners[first[i]]->key)) {
      entries.push_back({CellOf(corners[first[i]]->point, h), i});
    }
  }
  const PointGrid grid(h, entries);
  for (const auto& entry : entries) {
    const std::uint32_t i = entry.second;  // named: clang 14 cannot capture a structured binding
    const Vec3& p = corners[first[i]]->point;
    grid.ForEachNear(
        p - Vec3::Constant(distance), p + Vec3::Constant(distance), [&](std::uint32_t j) {
          if (j <= i || sets.Find(i) == sets.Find(j)) return;
          if ((corners[first[j]]->point - p).cwiseAbs().maxCoeff() > distance) return;
          if (partition::SamePoint(cx, corners[first[i]]->key, corners[first[j]]->key))
            sets.Union(i, j);
        });
  }
  // A point's vertex is numbered by the earliest occurrence among its triples.
  std::vector<DistinctKeyId> earliest(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::size_t root = sets.Find(i);
    if (!earliest[root].IsValid() ||
        corners[first[i]]->rank < corners[first[earliest[root].index()]]->rank) {
      earliest[root] = DistinctKeyId(i);
    }
  }
  std::vector<std::uint32_t> roots;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (sets.Find(i) == i) roots.push_back(i);
  }
  std::sort(roots.begin(), roots.end(), [&](std::uint32_t a, std::uint32_t b) {
    return corners[first[earliest[a].index()]]->rank < corners[first[earliest[b].index()]]->rank;
  });
  MergedVertices out;
  std::vector<CandidateVertexId> vertex_of_root(n);
  for (const std::uint32_t r : roots) {
    vertex_of_root[r] = CandidateVertexId(out.keys.size());
    const RawCorner& c = *corners[first[earliest[r].index()]];
    out.keys.push_back(c.key);
    out.points.push_back(c.point);
    out.on_face.push_back(partition::OnSomeBlockFace(c.key) ? 1 : 0);
  }
  out.merged_keys = n - roots.size();
  out.of_corner.resize(corners.size());
  for (std::size_t c = 0; c < corners.size(); ++c) {
    out.of_corner[c] = vertex_of_root[sets.Find(distinct_of_corner[c])].value();
  }
  return out;
}

/// An edge on a block face, as a corner of a face, before edge ids are assigned.
struct LineCorner {
  std::uint32_t lo;  ///< smaller vertex id of the edge
  std::uint32_t hi;
  std::uint32_t corner;
  std::uint32_t face;
  PlaneKey p;
  PlaneKey q;
};

/// One face's corners after vertices on its edges are inserted.
struct SubdividedFace {
  std::vector<std::uint32_t> vertices;
  std::vector<SurfaceEdgeId> edges;  ///< block edge id, or invalid for an edge on a face
  std::vector<std::pair<PlaneKey, PlaneKey>> lines;
};

SubdividedFace Subdivide(const BlockComplexes& cx,
                         const MergedVertices& mv,
                         const PointGrid& on_faces,
                         double distance,
                         const std::vector<const RawCorner*>& corners,
                         std::uint32_t begin,
                         std::uint32_t end) {
  SubdividedFace out;
  std::vector<std::uint32_t> inside;
  std::vector<VertexKey> keys;
  for (std::uint32_t k = begin; k < end; ++k) {
    const RawCorner& c = *corners[k];
    const std::uint32_t u = mv.of_corner[k];
    const std::uint32_t v = mv.of_corner[k + 1 < end ? k + 1 : begin];
    LINESURF_THROW_IF(
        u == v, kInternal, kExtractBlockSurfaceStage, "two corners of a face are one point");
    out.vertices.push_back(u);
    out.edges.push_back(c.edge);
    out.lines.push_back({c.p, c.q});
    if (c.edge.IsValid()) continue;
    const KeySegment segment{mv.keys[u], mv.keys[v], c.p, c.q};
    const Vec3 pad = Vec3::Constant(distance);
    const Vec3 lo = mv.points[u].cwiseMin(mv.points[v]) - pad;
    const Vec3 hi = mv.points[u].cwiseMax(mv.points[v]) + pad;
    inside.clear();
    on_faces.ForEachNear(lo, hi, [&](std::uint32_t w) {
      if (w == u || w == v) return;
      const Vec3& x = mv.points[w];
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) return;
      if (partition::StrictlyInside(cx, segment, mv.keys[w])) inside.push_back(w);
    });
    if (inside.empty()) continue;
    keys.clear();
    for (const std::uint32_t w : inside) keys.push_back(mv.keys[w]);
    partition::SortAlong(cx, segment, keys);
    for (const VertexKey& key : keys) {
      const auto it = std::find_if(
          inside.begin(), inside.end(), [&](std::uint32_t w) { return mv.keys[w] == key; });
      out.vertices.push_back(*it);
      out.edges.push_back(SurfaceEdgeId::Invalid());
      out.lines.push_back({c.p, c.q});
    }
  }
  return out;
}

/// The edges where a face continues flat into its partner: both on one plane with one outward
/// normal, across an edge that no other face meets (a crowded edge carries other faces, which
/// must keep it). Block faces split a wall into such pieces, and so do the lines where planes
/// without surface there cut it.
std::vector<FlatJoin> FlatJoins(const SurfaceCycles& s,
                                const std::vector<const RawFace*>& faces,
                                const std::vector<EdgePair>& crowded) {
  std::vector<SurfaceEdgeId> crowded_edges;
  for (const EdgePair& p : crowded) crowded_edges.push_back(p.edge);
  std::sort(crowded_edges.begin(), crowded_edges.end());
  std::vector<FlatJoin> joins;
  for (std::uint32_t f = 0; f < s.NumFaces(); ++f) {
    for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) {
      const SurfaceFaceId g = s.partner[k];
      if (!g.IsValid() || g.value() <= f || faces[f]->plane != faces[g.index()]->plane ||
          faces[f]->normal != faces[g.index()]->normal ||
          std::binary_search(crowded_edges.begin(), crowded_edges.end(), s.corner_edge[k])) {
        continue;
      }
      joins.push_back({s.corner_edge[k], SurfaceFaceId(f), g});
    }
  }
  return joins;
}

/// Pairs the faces on every edge that lies on a block face; appends pairs of edges with more
/// than two faces to `crowded`; returns the number of such edges and of all edges.
std::pair<std::size_t, std::size_t> PairOnFaces(const BlockComplexes& cx,
                                                const MergedVertices& mv,
                                                const std::vector<const RawFace*>& faces,
                                                std::vector<LineCorner>& line_corners,
                                                std::uint32_t first_edge_id,
                                                SurfaceCycles& s,
                                                std::vector<EdgePair>& crowded) {
  std::sort(line_corners.begin(), line_corners.end(), [](const LineCorner& a, const LineCorner& b) {
    return std::tie(a.lo, a.hi, a.corner) < std::tie(b.lo, b.hi, b.corner);
  });
  std::size_t non_manifold = 0;
  std::uint32_t edge = first_edge_id;
  std::vector<partition::EdgeFace> around;
  for (std::size_t i = 0; i < line_corners.size(); ++edge) {
    std::size_t j = i;
    while (j < line_corners.size() && line_corners[j].lo == line_corners[i].lo &&
           line_corners[j].hi == line_corners[i].hi) {
      s.corner_edge[line_corners[j].corner] = SurfaceEdgeId(edge);
      ++j;
    }
    const std::size_t m = j - i;
    const auto direction = [&](std::size_t k) {
      return s.corner_vertex[line_corners[k].corner] == line_corners[k].lo ? 1 : -1;
    };
    LINESURF_THROW_IF(m % 2 != 0,
                      kInternal,
                      kExtractBlockSurfaceStage,
                      "an edge on a block face has " << m << " surface faces");
    if (m == 2) {
      LINESURF_THROW_IF(
          direction(i) == direction(i + 1) || line_corners[i].face == line_corners[i + 1].face,
          kInternal,
          kExtractBlockSurfaceStage,
          "the two faces on an edge are not oriented alike");
      const SurfaceFaceId a(line_corners[i].face);
      const SurfaceFaceId b(line_corners[i + 1].face);
      s.partner[line_corners[i].corner] = b;
      s.partner[line_corners[i + 1].corner] = a;
    } else {
      ++non_manifold;
      around.clear();
      for (std::size_t k = i; k < j; ++k) {
        around.push_back({faces[line_corners[k].face]->normal, direction(k)});
      }
      const LineCorner& first = line_corners[i];
      const KeySegment segment{mv.keys[first.lo], mv.keys[first.hi], first.p, first.q};
      const std::vector<std::uint32_t> order = partition::OrderAroundEdge(cx, segment, around);
      // A face running from hi to lo has its full side counter-clockwise about lo -> hi: it is
      // joined to the next face in that order, which must run from lo to hi.
      for (std::size_t k = 0; k < m; ++k) {
        if (around[order[k]].direction > 0) continue;
        const LineCorner& a = line_corners[i + order[k]];
        const std::uint32_t next = order[(k + 1) % m];
        LINESURF_THROW_IF(around[next].direction < 0,
                          kInternal,
                          kExtractBlockSurfaceStage,
                          "faces around an edge on a block face do not alternate");
        const LineCorner& b = line_corners[i + next];
        s.partner[a.corner] = SurfaceFaceId(b.face);
        s.partner[b.corner] = SurfaceFaceId(a.face);
        crowded.push_back({SurfaceEdgeId(edge), SurfaceFaceId(a.face), SurfaceFaceId(b.face)});
      }
    }
    i = j;
  }
  return {non_manifold, edge - first_edge_id};
}

double SceneMagnitude(const BlockComplexes& cx) {
  const Box3& box = cx.grid.box();
  return 1.0 + std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
}


/// Where each block's pieces start: its seams among those listed by (lower block, axis) and its
/// edges, numbered consecutively over the blocks.
struct BlockNumbering {
  std::vector<std::uint32_t> seam_begin;
  std::vector<std::uint32_t> edge_offset;
};

BlockNumbering NumberBlocks(const BlockComplexes& cx) {
  const std::size_t num_blocks = cx.blocks.size();
  BlockNumbering n{std::vector<std::uint32_t>(num_blocks + 1, 0),
                   std::vector<std::uint32_t>(num_blocks + 1, 0)};
  for (const SeamFace& seam : cx.seams) ++n.seam_begin[seam.lower_block + 1];
  for (std::size_t b = 0; b < num_blocks; ++b) n.seam_begin[b + 1] += n.seam_begin[b];
  for (std::size_t b = 0; b < num_blocks; ++b) {
    n.edge_offset[b + 1] =
        n.edge_offset[b] + static_cast<std::uint32_t>(cx.blocks[b].complex.NumEdges());
  }
  return n;
}

/// The surface faces of every block, blocks in parallel.
std::vector<BlockPart> CollectParts(const BlockComplexes& cx,
                                    const Collector& collector,
                                    const BlockNumbering& numbering,
                                    const RunContext& ctx) {
  const std::vector<std::uint32_t>& seam_begin = numbering.seam_begin;
  std::vector<BlockPart> parts(cx.blocks.size());
  RunInArena(ctx, [&] {
    tbb::parallel_for(std::size_t{0}, cx.blocks.size(), [&](std::size_t b) {
      if (ctx.ShouldStop()) return;
      const std::span<const SeamFace> lower(cx.seams.data() + seam_begin[b],
                                            seam_begin[b + 1] - seam_begin[b]);
      parts[b] = collector.Collect(b, numbering.edge_offset[b], lower, seam_begin[b]);
    });
  });
  ctx.ThrowIfCancelled(kExtractBlockSurfaceStage);
  return parts;
}

/// All faces and corners of the parts in output order.
struct OrderedFaces {
  std::vector<const RawCorner*> corners;
  std::vector<const RawFace*> faces;
  std::vector<std::uint32_t> face_begin;  ///< first corner of each face in `corners`, then the end
  std::vector<std::uint32_t> block_first_face;
};

OrderedFaces OrderFaces(const std::vector<BlockPart>& parts, StitchStats& stitch) {
  OrderedFaces o;
  o.block_first_face.assign(parts.size() + 1, 0);
  for (std::size_t b = 0; b < parts.size(); ++b) {
    const auto base = static_cast<std::uint32_t>(o.corners.size());
    for (const RawCorner& c : parts[b].corners) o.corners.push_back(&c);
    for (const RawFace& f : parts[b].faces) {
      o.faces.push_back(&f);
      o.face_begin.push_back(base + f.begin);
      stitch.seam_surface_facets += f.ref.seam ? 1 : 0;
    }
    o.block_first_face[b + 1] = static_cast<std::uint32_t>(o.faces.size());
  }
  o.face_begin.push_back(static_cast<std::uint32_t>(o.corners.size()));
  return o;
}

/// Every face with the vertices on block faces that lie inside its edges inserted, faces in
/// parallel.
std::vector<SubdividedFace> SubdivideFaces(const BlockComplexes& cx,
                                           const MergedVertices& mv,
                                           const OrderedFaces& o,
                                           double distance,
                                           const RunContext& ctx) {
  // Vertices on block faces, for the search of vertices inside edges.
  const Vec3 extent = cx.grid.box().Extent();
  const double cell = std::min(cx.grid.block_size(), extent.maxCoeff()) / kEdgeSearchCellsPerBlock;
  std::vector<std::pair<Cell3, std::uint32_t>> entries;
  for (std::uint32_t v = 0; v < mv.keys.size(); ++v) {
    if (mv.on_face[v] != 0) entries.push_back({CellOf(mv.points[v], cell), v});
  }
  const PointGrid on_faces(cell, std::move(entries));
  std::vector<SubdividedFace> subdivided(o.faces.size());
  RunInArena(ctx, [&] {
    tbb::parallel_for(std::size_t{0}, o.faces.size(), [&](std::size_t f) {
      if (ctx.ShouldStop()) return;
      subdivided[f] =
          Subdivide(cx, mv, on_faces, distance, o.corners, o.face_begin[f], o.face_begin[f + 1]);
    });
  });
  ctx.ThrowIfCancelled(kExtractBlockSurfaceStage);
  return subdivided;
}

/// The subdivided faces as cycles, unpaired; the corners whose edge lies on a block face go to
/// `line_corners`.
SurfaceCycles BuildCycles(const std::vector<SubdividedFace>& subdivided,
                          const OrderedFaces& o,
                          std::vector<LineCorner>& line_corners,
                          StitchStats& stitch) {
  SurfaceCycles s;
  for (std::size_t f = 0; f < subdivided.size(); ++f) {
    const SubdividedFace& sub = subdivided[f];
    const std::size_t n = sub.vertices.size();
    stitch.inserted_vertices += n - (o.face_begin[f + 1] - o.face_begin[f]);
    for (std::size_t k = 0; k < n; ++k) {
      const auto corner = static_cast<std::uint32_t>(s.corner_vertex.size());
      s.corner_vertex.push_back(sub.vertices[k]);
      s.corner_edge.push_back(sub.edges[k]);
      s.partner.push_back(SurfaceFaceId::Invalid());
      if (!sub.edges[k].IsValid()) {
        const std::uint32_t a = sub.vertices[k];
        const std::uint32_t b = sub.vertices[(k + 1) % n];
        line_corners.push_back({std::min(a, b),
                                std::max(a, b),
                                corner,
                                static_cast<std::uint32_t>(f),
                                sub.lines[k].first,
                                sub.lines[k].second});
      }
    }
    s.offsets.push_back(static_cast<std::uint32_t>(s.corner_vertex.size()));
  }
  return s;
}

/// Pairs the faces across every edge: edges off the shared faces from each block's edge stars,
/// blocks in parallel (each writes the partners of its own faces only), then the edges on block
/// faces. Returns the pairs of edges with more than two faces.
std::vector<EdgePair> PairFaces(const BlockComplexes& cx,
                                std::span<const std::uint8_t> labels,
                                const std::vector<std::size_t>& cell_offsets,
                                bool outside_full,
                                const std::vector<BlockPart>& parts,
                                const BlockNumbering& numbering,
                                const OrderedFaces& o,
                                const MergedVertices& mv,
                                std::vector<LineCorner>& line_corners,
                                SurfaceCycles& s,
                                BlockExtractResult& result,
                                const RunContext& ctx) {
  const std::size_t num_blocks = cx.blocks.size();
  std::vector<std::vector<EdgePair>> block_crowded(num_blocks);
  std::vector<std::size_t> block_non_manifold(num_blocks, 0);
  RunInArena(ctx, [&] {
    tbb::parallel_for(std::size_t{0}, num_blocks, [&](std::size_t b) {
      const CellComplex& c = cx.blocks[b].complex;
      std::vector<SurfaceFaceId> face_of_facet = parts[b].face_of_facet;
      for (SurfaceFaceId& f : face_of_facet) {
        if (f.IsValid()) f = SurfaceFaceId(f.value() + o.block_first_face[b]);
      }
      block_non_manifold[b] = PairAroundComplexEdges(c,
                                                     labels.subspan(cell_offsets[b], c.NumCells()),
                                                     outside_full,
                                                     face_of_facet,
                                                     numbering.edge_offset[b],
                                                     parts[b].seam_facet,
                                                     s,
                                                     block_crowded[b]);
    });
  });
  std::vector<EdgePair> crowded;
  for (std::size_t b = 0; b < num_blocks; ++b) {
    crowded.insert(crowded.end(), block_crowded[b].begin(), block_crowded[b].end());
    result.stats.non_manifold_edges += block_non_manifold[b];
  }
  const auto [non_manifold, on_faces_edges] =
      PairOnFaces(cx, mv, o.faces, line_corners, numbering.edge_offset.back(), s, crowded);
  result.stats.non_manifold_edges += non_manifold;
  result.stitch.edges_on_block_faces = on_faces_edges;
  return crowded;
}

/// The mesh of the paired cycles (coplanar faces merged first when asked), with the facet of
/// every output face and the triple of every output vertex.
void AssembleResult(SurfaceCycles s,
                    std::vector<EdgePair> crowded,
                    const OrderedFaces& o,
                    const MergedVertices& mv,
                    const ExtractOptions& options,
                    BlockExtractResult& result) {
  // Faces of the cycles -> the first facet each stands for.
  std::vector<std::uint32_t> first_face(s.NumFaces());
  for (std::uint32_t f = 0; f < first_face.size(); ++f) first_face[f] = f;
  if (options.merge_coplanar) {
    MergedCycles merged =
        MergeAcrossJoins(s, FlatJoins(s, o.faces, crowded), crowded, mv.points.size());
    s = std::move(merged.cycles);
    crowded = std::move(merged.crowded);
    first_face = std::move(merged.first_face);
    result.stitch.merged_faces = merged.merged_faces;
  }
  AssembledSurface surface = AssembleSurface(s, mv.points, crowded, options.triangulate);
  result.mesh = std::move(surface.mesh);
  result.stats.surface_facets = o.faces.size();
  result.stats.split_vertices = surface.split_vertices;
  result.face_facet.reserve(surface.face_cycle.size());
  for (const std::uint32_t f : surface.face_cycle) {
    result.face_facet.push_back(o.faces[first_face[f]]->ref);
  }
  result.vertex_key.reserve(surface.vertex_source.size());
  for (const CandidateVertexId v : surface.vertex_source) {
    result.vertex_key.push_back(v.IsValid() ? std::optional<VertexKey>(mv.keys[v.index()])
                                            : std::nullopt);
  }
}

}  // namespace

Expected<BlockExtractResult> ExtractBlockSurface(const BlockComplexes& cx,
                                                 std::span<const std::uint8_t> labels,
                                                 const ExtractOptions& options,
                                                 const RunContext& ctx) noexcept {
  return CatchAll(kExtractBlockSurfaceStage, [&]() -> BlockExtractResult {
    const std::vector<std::size_t> cell_offsets = partition::GlobalCellOffsets(cx);
    LINESURF_THROW_IF(options.merge_coplanar && options.triangulate,
                      kInvalidOptions,
                      kExtractBlockSurfaceStage,
                      "merge_coplanar gives non-convex faces: not with triangulate");
    LINESURF_THROW_IF(
        labels.size() != cell_offsets.back(),
        kInvalidInput,
        kExtractBlockSurfaceStage,
        "labels has " << labels.size() << " entries for " << cell_offsets.back() << " cells");
    const BlockNumbering numbering = NumberBlocks(cx);
    const Collector collector(cx, labels, cell_offsets, options.outside_full);
    const std::vector<BlockPart> parts = CollectParts(cx, collector, numbering, ctx);

    BlockExtractResult result;
    const OrderedFaces ordered = OrderFaces(parts, result.stitch);
    const double distance = kCandidateDistance * SceneMagnitude(cx);
    const MergedVertices mv = MergeVertices(cx, ordered.corners, distance);
    result.stitch.merged_vertex_keys = mv.merged_keys;

    std::vector<LineCorner> line_corners;
    SurfaceCycles s = BuildCycles(
        SubdivideFaces(cx, mv, ordered, distance, ctx), ordered, line_corners, result.stitch);
    std::vector<EdgePair> crowded = PairFaces(cx,
                                              labels,
                                              cell_offsets,
                                              options.outside_full,
                                              parts,
                                              numbering,
                                              ordered,
                                              mv,
                                              line_corners,
                                              s,
                                              result,
                                              ctx);
    AssembleResult(std::move(s), std::move(crowded), ordered, mv, options, result);
    return result;
  });
}

}  // namespace linesurf::pipeline
