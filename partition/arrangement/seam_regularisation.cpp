#include "partition/arrangement/seam_regularisation.h"

#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "partition/arrangement/exact_predicates.h"
#include "partition/arrangement/seam_overlay.h"
#include "partition/arrangement/vertex_key_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <numeric>
#include <utility>

namespace linesurf::partition {
namespace {

constexpr char kSeamRegularisationStage[] = "seam_regularisation";

/// Pieces of an edge shorter than this fraction of the block size are rounding slivers between
/// breakpoints that are one point exactly.
constexpr double kMinPieceRelative = 1e-12;

/// The local plane of block `block` with global key `key`, or invalid.
ComplexPlaneId LocalPlane(const BlockComplex& block, PlaneKey key) {
  const auto& keys = block.plane_keys;
  if (key.IsFace()) {
    for (std::size_t k = 0; k < kNumBoxPlanes; ++k) {
      if (keys[k] == key) return ComplexPlaneId(k);
    }
    return ComplexPlaneId();
  }
  const auto first = keys.begin() + static_cast<std::ptrdiff_t>(kNumBoxPlanes);
  const auto it = std::lower_bound(first, keys.end(), key);
  return it != keys.end() && *it == key
             ? ComplexPlaneId(static_cast<std::size_t>(it - keys.begin()))
             : ComplexPlaneId();
}

/// +1 when the local plane's coefficients are the global key's, -1 when negated (the box planes
/// of the maximum faces have inward normals, the face keys increasing coordinates).
int LocalOrientation(ComplexPlaneId local) {
  return local.index() >= kNumBoxPlanes / 2 && local.index() < kNumBoxPlanes ? -1 : 1;
}

/// The side (+1/-1, in the global orientation of q) of cell c of block b, or 0 when q cuts the
/// cell (some vertex strictly on each side: convex cells). A plane of the block never cuts its
/// cells, so the first vertex off it decides; for another block's plane every vertex counts.
int CellSideOf(const BlockComplexes& cx, std::size_t b, CellId c, PlaneKey q) {
  const BlockComplex& block = cx.blocks[b];
  const CellComplex& k = block.complex;
  const ComplexPlaneId local = LocalPlane(block, q);
  if (local.IsValid()) {
    for (const FacetId f : k.cell_facets[c]) {
      if (k.facet_plane[f] != local) continue;
      return LocalOrientation(local) * (k.facet_positive_cell[f] == c ? 1 : -1);
    }
  }
  bool positive = false;
  bool negative = false;
  std::vector<VertexId> seen;
  for (const FacetId f : k.cell_facets[c]) {
    for (const VertexId v : k.facet_vertices[f]) {
      if (std::find(seen.begin(), seen.end(), v) != seen.end()) continue;
      seen.push_back(v);
      const int s = SignAt(cx, BlockVertexKey(block, v), q);
      positive |= s > 0;
      negative |= s < 0;
      if (positive && negative) return 0;
      if (s != 0 && local.IsValid()) return s;
    }
  }
  return positive ? 1 : -1;
}

/// nu of the cells around an element through the planes `through` (sorted), each cell dropped
/// when some plane through the element cuts it.
SeamParityGroup SignedCells(const BlockComplexes& cx,
                            const std::vector<BlockCell>& cells,
                            const std::vector<PlaneKey>& through,
                            bool& dropped) {
  SeamParityGroup group;
  for (const BlockCell& c : cells) {
    int nu = 1;
    for (const PlaneKey q : through) {
      nu *= CellSideOf(cx, c.block, c.cell, q);
      if (nu == 0) break;
    }
    if (nu == 0) {
      dropped = true;
      continue;
    }
    group.cells.push_back(c);
    group.signs.push_back(static_cast<std::int8_t>(nu));
  }
  return group;
}

bool OnSceneBox(const BlockGrid& grid, PlaneKey face) {
  return face.face_index() == 0 || face.face_index() == grid.dims()[face.axis()];
}

// ---- edges ----------------------------------------------------------------------------------

/// An edge of one block lying on its box but not on the scene box: on a block face (its facet
/// chain starts and ends on that face) or on a block edge (on two faces).
struct BoundaryEdge {
  std::uint32_t block = 0;
  EdgeId edge;
  std::vector<PlaneKey> faces;     ///< sorted, 1 or 2
  std::vector<PlaneKey> carriers;  ///< input planes through the edge, sorted
  Vec3 p0 = Vec3::Zero();
  Vec3 p1 = Vec3::Zero();
};

std::vector<BoundaryEdge> BoundaryEdges(const BlockComplexes& cx, std::uint32_t b) {
  const BlockComplex& block = cx.blocks[b];
  const CellComplex& k = block.complex;
  std::vector<BoundaryEdge> out;
  for (std::size_t e = 0; e < k.NumEdges(); ++e) {
    const EdgeId id(e);
    const auto facets = k.edge_facets[id];
    if (k.edge_cells[id].size() == facets.size()) continue;  // closed: inside the block
    BoundaryEdge edge;
    edge.block = b;
    edge.edge = id;
    bool on_scene_box = false;
    for (const FacetId f : facets) {
      const PlaneKey key = block.plane_keys[k.facet_plane[f].index()];
      if (key.IsFace()) {
        on_scene_box |= OnSceneBox(cx.grid, key);
        edge.faces.push_back(key);
      } else {
        edge.carriers.push_back(key);
      }
    }
    if (on_scene_box) continue;
    for (auto* v : {&edge.faces, &edge.carriers}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const auto& ends = k.edge_vertices[id];
    edge.p0 = k.vertex_points[ends[0]];
    edge.p1 = k.vertex_points[ends[1]];
    out.push_back(std::move(edge));
  }
  return out;
}

/// The line of each boundary edge: (face keys, smallest carrier of its pencil on that face)
/// for an edge on one face, (the two face keys) for an edge on a block edge. Edges of
/// different blocks on one line share it: a plane reaching both blocks is a carrier of both.
std::vector<std::array<std::uint64_t, 3>> LineKeys(const std::vector<BoundaryEdge>& edges) {
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::size_t> ids;  // (face, carrier)
  std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
  const auto id_of = [&](PlaneKey face, PlaneKey carrier) {
    const auto key = std::make_pair(face.value(), carrier.value());
    const auto [it, added] = ids.emplace(key, pairs.size());
    if (added) pairs.push_back(key);
    return it->second;
  };
  for (const BoundaryEdge& e : edges) {
    if (e.faces.size() != 1) continue;
    for (const PlaneKey c : e.carriers) id_of(e.faces[0], c);
  }
  // Ids in (face, carrier) order, so that the smallest id of a set is its smallest carrier.
  std::sort(pairs.begin(), pairs.end());
  for (std::size_t i = 0; i < pairs.size(); ++i) ids[pairs[i]] = i;
  DisjointSets sets(pairs.size());
  for (const BoundaryEdge& e : edges) {
    if (e.faces.size() != 1) continue;
    for (std::size_t i = 1; i < e.carriers.size(); ++i) {
      sets.Union(ids[{e.faces[0].value(), e.carriers[0].value()}],
                 ids[{e.faces[0].value(), e.carriers[i].value()}]);
    }
  }
  std::vector<std::array<std::uint64_t, 3>> keys;
  keys.reserve(edges.size());
  for (const BoundaryEdge& e : edges) {
    if (e.faces.size() == 1 && !e.carriers.empty()) {
      const std::size_t root = sets.Find(ids[{e.faces[0].value(), e.carriers[0].value()}]);
      keys.push_back({1, e.faces[0].value(), pairs[root].second});
    } else {
      keys.push_back({2, e.faces.front().value(), e.faces.back().value()});
    }
  }
  return keys;
}

/// The pieces of one line: the overlay of the blocks' subdivisions of it, each piece with the
/// cells of every block's edge covering it.
void LinePieces(const BlockComplexes& cx,
                const std::vector<const BoundaryEdge*>& edges,
                std::size_t blocks_around,
                std::vector<SeamParityGroup>& out,
                std::size_t& with_dropped) {
  const Vec3 origin = edges.front()->p0;
  const Vec3 dir = (edges.front()->p1 - origin).normalized();
  std::vector<std::pair<double, double>> spans;
  std::vector<double> breaks;
  for (const BoundaryEdge* e : edges) {
    const double s0 = dir.dot(e->p0 - origin);
    const double s1 = dir.dot(e->p1 - origin);
    spans.emplace_back(std::min(s0, s1), std::max(s0, s1));
    breaks.push_back(s0);
    breaks.push_back(s1);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  const double min_piece = kMinPieceRelative * cx.grid.block_size();
  SeamParityGroup previous;
  const auto flush = [&] {
    if (!previous.cells.empty()) out.push_back(std::move(previous));
    previous = SeamParityGroup{};
  };
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double length = breaks[i + 1] - breaks[i];
    if (!(length > min_piece)) continue;
    const double mid = 0.5 * (breaks[i] + breaks[i + 1]);
    std::vector<BlockCell> cells;
    std::vector<PlaneKey> through;
    std::size_t blocks = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      if (!(spans[k].first < mid && mid < spans[k].second)) continue;
      ++blocks;
      const BoundaryEdge& e = *edges[k];
      for (const CellId c : cx.blocks[e.block].complex.edge_cells[e.edge]) {
        cells.push_back({e.block, c});
      }
      through.insert(through.end(), e.faces.begin(), e.faces.end());
      through.insert(through.end(), e.carriers.begin(), e.carriers.end());
    }
    if (cells.empty()) {
      flush();
      continue;
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    std::sort(through.begin(), through.end());
    through.erase(std::unique(through.begin(), through.end()), through.end());
    bool dropped = blocks < blocks_around;
    SeamParityGroup group = SignedCells(cx, cells, through, dropped);
    with_dropped += dropped ? 1 : 0;
    group.length = length;
    if (group.cells.empty()) {
      flush();
      continue;
    }
    if (group.cells == previous.cells && group.signs == previous.signs) {
      previous.length += length;
      continue;
    }
    flush();
    previous = std::move(group);
  }
  flush();
}

// ---- vertices -------------------------------------------------------------------------------

/// A point on block boundaries as some triple of global keys, with its rounded coordinates.
struct RawVertex {
  VertexKey key;
  Vec3 point = Vec3::Zero();
};

/// A vertex on block boundaries off the scene box: its canonical triple, the blocks holding it
/// and every plane through it.
struct SeamVertex {
  VertexKey key;
  std::vector<std::uint32_t> blocks;
  std::vector<PlaneKey> through;
};

/// The blocks holding the point along one axis (1 or 2 indices), or none on the scene box.
std::vector<int> AxisBlocks(const BlockComplexes& cx, const RawVertex& v, int axis) {
  const int n = cx.grid.dims()[axis];
  const auto sign = [&](int face) { return SignAt(cx, v.key, PlaneKey::Face(axis, face)); };
  int i = cx.grid.LocateAxis(axis, v.point[axis]);
  while (i > 0 && sign(i) < 0) --i;
  while (i + 1 < n && sign(i + 1) > 0) ++i;
  if ((i == 0 && sign(0) == 0) || (i == n - 1 && sign(n) == 0)) return {};
  if (sign(i) == 0) return {i - 1, i};
  if (sign(i + 1) == 0) return {i, i + 1};
  return {i};
}

/// The canonical form of a raw vertex (nullopt-like: empty blocks when on the scene box).
SeamVertex Canonical(const BlockComplexes& cx, const RawVertex& v) {
  SeamVertex out;
  std::array<std::vector<int>, 3> axis_blocks;
  for (int a = 0; a < 3; ++a) {
    axis_blocks[a] = AxisBlocks(cx, v, a);
    if (axis_blocks[a].empty()) return out;
  }
  for (const int z : axis_blocks[2]) {
    for (const int y : axis_blocks[1]) {
      for (const int x : axis_blocks[0]) {
        out.blocks.push_back(
            static_cast<std::uint32_t>(cx.grid.LinearIndex(Eigen::Vector3i(x, y, z))));
      }
    }
  }
  std::sort(out.blocks.begin(), out.blocks.end());
  for (const std::uint32_t b : out.blocks) {
    for (const PlaneKey p : cx.blocks[b].plane_keys) {
      if (SignAt(cx, v.key, p) == 0) out.through.push_back(p);
    }
  }
  std::sort(out.through.begin(), out.through.end());
  out.through.erase(std::unique(out.through.begin(), out.through.end()), out.through.end());
  // The smallest triple of independent planes through the point names it.
  const std::size_t n = out.through.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        const Vec3 a = cx.Coefficients(out.through[i]).head<3>();
        const Vec3 b = cx.Coefficients(out.through[j]).head<3>();
        const Vec3 c = cx.Coefficients(out.through[k]).head<3>();
        if (ExactSignDet3(a, b, c) != 0) {
          out.key = {out.through[i], out.through[j], out.through[k]};
          return out;
        }
      }
    }
  }
  out.blocks.clear();  // unreachable: the raw triple itself is independent
  return out;
}

/// The cells of block b whose closure holds the vertex: a walk to one of them over the planes
/// off the vertex, then across the facets on planes through it.
std::vector<CellId> Star(const BlockComplexes& cx, std::uint32_t b, const VertexKey& key) {
  const CellComplex& k = cx.blocks[b].complex;
  const Eigen::Vector4d p0 = cx.Coefficients(key[0]);
  const Eigen::Vector4d p1 = cx.Coefficients(key[1]);
  const Eigen::Vector4d p2 = cx.Coefficients(key[2]);
  std::vector<std::int8_t> side(k.planes.size(), 2);  // 2 = not computed
  const auto sign = [&](ComplexPlaneId p) {
    std::int8_t& s = side[p.index()];
    if (s == 2)
      s = static_cast<std::int8_t>(ExactSignAtVertex(p0, p1, p2, k.planes[p].coefficients));
    return s;
  };
  CellId c(std::uint32_t{0});
  for (std::size_t step = 0; step <= k.planes.size(); ++step) {
    FacetId wrong;
    for (const FacetId f : k.cell_facets[c]) {
      const int s = sign(k.facet_plane[f]);
      if (s != 0 && s != (k.facet_positive_cell[f] == c ? 1 : -1)) {
        wrong = f;
        break;
      }
    }
    if (!wrong.IsValid() || k.IsBoxFacet(wrong)) break;
    c = k.Neighbour(wrong, c);
  }
  std::vector<CellId> star{c};
  for (std::size_t i = 0; i < star.size(); ++i) {
    for (const FacetId f : k.cell_facets[star[i]]) {
      if (k.IsBoxFacet(f) || sign(k.facet_plane[f]) != 0) continue;
      const CellId n = k.Neighbour(f, star[i]);
      if (std::find(star.begin(), star.end(), n) == star.end()) star.push_back(n);
    }
  }
  std::sort(star.begin(), star.end());
  return star;
}

template <typename Fn>
bool ParallelFor(const RunContext& ctx, std::size_t n, Fn&& fn) {
  std::atomic<bool> stopped{false};
  RunInArena(ctx, [&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
          if (stopped.load(std::memory_order_relaxed) || ctx.ShouldStop()) {
            stopped.store(true, std::memory_order_relaxed);
            return;
          }
          for (std::size_t i = r.begin(); i != r.end(); ++i) fn(i);
        },
        tbb::simple_partitioner{});
  });
  return !stopped.load();
}

// The edge pieces on block faces and block edges (out.edges, out.edges_with_dropped_cells): every
// block's boundary edges, grouped by line, pieces along each line. Its temporaries (two
// vectors per boundary edge, the per-line groups) are gone before the vertices are built, which
// lowers the stage's peak. Returns false when cancelled.
bool AddSeamEdges(const BlockComplexes& cx, const RunContext& ctx, SeamRegularisation& out) {
  std::vector<BoundaryEdge> edges;
  {
    std::vector<std::vector<BoundaryEdge>> per_block(cx.blocks.size());
    if (!ParallelFor(ctx, cx.blocks.size(), [&](std::size_t b) {
          per_block[b] = BoundaryEdges(cx, static_cast<std::uint32_t>(b));
        })) {
      return false;
    }
    std::size_t total = 0;
    for (const auto& list : per_block) total += list.size();
    edges.reserve(total);
    for (auto& list : per_block) {
      for (auto& e : list) edges.push_back(std::move(e));
    }
  }
  const std::vector<std::array<std::uint64_t, 3>> line_keys = LineKeys(edges);
  std::vector<std::size_t> order(edges.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return line_keys[a] < line_keys[b];
  });
  std::vector<std::pair<std::size_t, std::size_t>> lines;  // ranges of `order`
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && line_keys[order[j]] == line_keys[order[i]]) ++j;
    lines.emplace_back(i, j);
    i = j;
  }
  std::vector<std::vector<SeamParityGroup>> line_groups(lines.size());
  std::vector<std::size_t> line_dropped(lines.size(), 0);
  if (!ParallelFor(ctx, lines.size(), [&](std::size_t l) {
        std::vector<const BoundaryEdge*> on_line;
        for (std::size_t i = lines[l].first; i < lines[l].second; ++i) {
          on_line.push_back(&edges[order[i]]);
        }
        const std::size_t around = line_keys[order[lines[l].first]][0] == 1 ? 2 : 4;
        LinePieces(cx, on_line, around, line_groups[l], line_dropped[l]);
      })) {
    return false;
  }
  std::size_t pieces = 0;
  for (const auto& groups : line_groups) pieces += groups.size();
  out.edges.reserve(pieces);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    out.edges_with_dropped_cells += line_dropped[l];
    for (auto& g : line_groups[l]) out.edges.push_back(std::move(g));
  }
  return true;
}

// The vertices on block faces, edges and corners (out.vertices): every point on block
// boundaries named by a block or a seam facet, once. Returns false when cancelled.
bool AddSeamVertices(const BlockComplexes& cx, const RunContext& ctx, SeamRegularisation& out) {
  std::vector<RawVertex> raw;
  for (const BlockComplex& block : cx.blocks) {
    const CellComplex& k = block.complex;
    for (std::size_t v = 0; v < k.NumVertices(); ++v) {
      if (k.vertex_planes[VertexId(v)][0].index() >= kNumBoxPlanes) continue;  // off the box
      raw.push_back({BlockVertexKey(block, VertexId(v)), k.vertex_points[VertexId(v)]});
    }
  }
  for (const SeamFace& face : cx.seams) {
    for (const SeamFacet& f : face.facets) {
      for (std::size_t i = 0; i < f.vertices.size(); ++i)
        raw.push_back({f.vertices[i], f.points[i]});
    }
  }
  std::stable_sort(
      raw.begin(), raw.end(), [](const RawVertex& a, const RawVertex& b) { return a.key < b.key; });
  raw.erase(std::unique(raw.begin(),
                        raw.end(),
                        [](const RawVertex& a, const RawVertex& b) { return a.key == b.key; }),
            raw.end());
  std::vector<SeamVertex> vertices(raw.size());
  if (!ParallelFor(ctx, raw.size(), [&](std::size_t i) { vertices[i] = Canonical(cx, raw[i]); })) {
    return false;
  }
  std::erase_if(vertices, [](const SeamVertex& v) { return v.blocks.empty(); });
  std::stable_sort(vertices.begin(), vertices.end(), [](const SeamVertex& a, const SeamVertex& b) {
    return a.key < b.key;
  });
  vertices.erase(
      std::unique(vertices.begin(),
                  vertices.end(),
                  [](const SeamVertex& a, const SeamVertex& b) { return a.key == b.key; }),
      vertices.end());
  out.vertices.resize(vertices.size());
  if (!ParallelFor(ctx, vertices.size(), [&](std::size_t i) {
        std::vector<BlockCell> cells;
        for (const std::uint32_t b : vertices[i].blocks) {
          for (const CellId c : Star(cx, b, vertices[i].key)) cells.push_back({b, c});
        }
        bool dropped = false;
        out.vertices[i] = SignedCells(cx, cells, vertices[i].through, dropped);
      })) {
    return false;
  }
  std::erase_if(out.vertices, [](const SeamParityGroup& g) { return g.cells.empty(); });
  return true;
}

}  // namespace

Expected<SeamRegularisation> ComputeSeamRegularisation(const BlockComplexes& cx,
                                                       const RunContext& ctx) noexcept {
  return CatchAll(kSeamRegularisationStage, [&]() -> SeamRegularisation {
    SeamRegularisation out;
    if (!AddSeamEdges(cx, ctx, out) || !AddSeamVertices(cx, ctx, out)) {
      throw LinesurfException(Error{ErrorCode::kCancelled, kSeamRegularisationStage, "cancelled"});
    }
    return out;
  });
}

}  // namespace linesurf::partition
