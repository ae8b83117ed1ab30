#include "partition/arrangement/validate_cell_complex.h"

#include <algorithm>
#include <sstream>

#include "engine/core/exception.h"
#include "partition/arrangement/cell_geometry.h"
#include "partition/arrangement/exact_predicates.h"

namespace linesurf::partition {
namespace {

constexpr char kValidateCellComplexStage[] = "validate_cell_complex";

#define LINESURF_CHECK(cond, msg) \
  LINESURF_THROW_IF(!(cond), kInternal, kValidateCellComplexStage, msg)

int SignAt(const CellComplex& cx, VertexId v, ComplexPlaneId p) {
  const auto& t = cx.vertex_planes[v];
  for (const ComplexPlaneId q : t) {
    if (q == p) return 0;
  }
  return ExactSignAtVertex(cx.planes[t[0]].coefficients, cx.planes[t[1]].coefficients,
                           cx.planes[t[2]].coefficients, cx.planes[p].coefficients);
}

/// The per-element arrays have one entry a vertex, edge, facet or cell.
void CheckSizes(const CellComplex& cx) {
  const std::size_t nv = cx.NumVertices(), ne = cx.NumEdges(), nf = cx.NumFacets(),
                    nc = cx.NumCells();
  LINESURF_CHECK(cx.planes.size() >= kNumBoxPlanes, "fewer than 6 planes");
  LINESURF_CHECK(cx.vertex_planes.size() == nv, "vertex arrays differ in size");
  LINESURF_CHECK(cx.edge_facets.NumRows() == ne && cx.edge_cells.NumRows() == ne,
                 "edge arrays differ in size");
  LINESURF_CHECK(cx.facet_positive_cell.size() == nf && cx.facet_negative_cell.size() == nf &&
                     cx.facet_vertices.NumRows() == nf && cx.facet_edges.NumRows() == nf,
                 "facet arrays differ in size");
  LINESURF_CHECK(cx.cell_colour.size() == nc, "cell arrays differ in size");
}

/// Vertices: sorted independent canonical triples.
void CheckVertices(const CellComplex& cx) {
  for (std::size_t i = 0; i < cx.NumVertices(); ++i) {
    const auto& t = cx.vertex_planes[VertexId(i)];
    LINESURF_CHECK(t[0] < t[1] && t[1] < t[2] && t[2].index() < cx.planes.size(),
                   "vertex " << i << ": triple not sorted or out of range");
    LINESURF_CHECK(ExactSignDet3(cx.planes[t[0]].coefficients.head<3>(),
                                 cx.planes[t[1]].coefficients.head<3>(),
                                 cx.planes[t[2]].coefficients.head<3>()) != 0,
                   "vertex " << i << ": dependent triple");
  }
}

/// Facet `f`: a cycle of at least 3 vertices on its plane, joined by its edges; a positive cell,
/// and a distinct negative cell of another colour unless on the box; listed once by its cells.
void CheckFacet(const CellComplex& cx, FacetId f) {
  const std::size_t i = f.index();
  const std::size_t nc = cx.NumCells();
  const auto cycle = cx.facet_vertices[f];
  const auto edges = cx.facet_edges[f];
  LINESURF_CHECK(cycle.size() >= 3, "facet " << i << ": fewer than 3 vertices");
  LINESURF_CHECK(edges.size() == cycle.size(), "facet " << i << ": edge count");
  LINESURF_CHECK(cx.facet_plane[f].index() < cx.planes.size(), "facet " << i << ": plane");
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    LINESURF_CHECK(SignAt(cx, cycle[k], cx.facet_plane[f]) == 0,
                   "facet " << i << ": vertex " << cycle[k].index() << " off its plane");
    const auto ev = cx.edge_vertices[edges[k]];
    const VertexId a = cycle[k], b = cycle[(k + 1) % cycle.size()];
    LINESURF_CHECK((ev[0] == std::min(a, b) && ev[1] == std::max(a, b)),
                   "facet " << i << ": edge " << k << " does not join its vertices");
  }
  const CellId pos = cx.facet_positive_cell[f], neg = cx.facet_negative_cell[f];
  LINESURF_CHECK(pos.IsValid() && pos.index() < nc, "facet " << i << ": no positive cell");
  if (cx.IsBoxFacet(f)) {
    LINESURF_CHECK(!neg.IsValid(), "box facet " << i << " has an outer cell");
  } else {
    LINESURF_CHECK(neg.IsValid() && neg.index() < nc && neg != pos,
                   "facet " << i << ": needs two distinct cells");
    LINESURF_CHECK(cx.cell_colour[pos] != cx.cell_colour[neg],
                   "facet " << i << ": adjacent cells share a colour");
  }
  for (const CellId c : {pos, neg}) {
    if (!c.IsValid()) continue;
    const auto fs = cx.cell_facets[c];
    LINESURF_CHECK(std::count(fs.begin(), fs.end(), f) == 1,
                   "facet " << i << " not listed once by its cell " << c.index());
  }
}

/// Cell `c`: its facets name it and lie on distinct planes, their outward cycles form a closed
/// oriented surface with Euler characteristic 2. `directed` and `planes` are scratch. Returns the
/// cell's vertices.
std::vector<VertexId> CheckCellSurface(const CellComplex& cx,
                      CellId c,
                      std::vector<std::pair<VertexId, VertexId>>& directed,
                      std::vector<ComplexPlaneId>& planes) {
  const std::size_t i = c.index();
  const auto fs = cx.cell_facets[c];
  LINESURF_CHECK(fs.size() >= 4, "cell " << i << ": fewer than 4 facets");
  directed.clear();
  planes.clear();
  for (const FacetId f : fs) {
    LINESURF_CHECK(cx.facet_positive_cell[f] == c || cx.facet_negative_cell[f] == c,
                   "cell " << i << ": facet " << f.index() << " does not name the cell");
    planes.push_back(cx.facet_plane[f]);
    const auto cycle = OutwardFacetCycle(cx, f, c);
    for (std::size_t k = 0; k < cycle.size(); ++k) {
      directed.emplace_back(cycle[k], cycle[(k + 1) % cycle.size()]);
    }
  }
  std::sort(planes.begin(), planes.end());
  LINESURF_CHECK(std::adjacent_find(planes.begin(), planes.end()) == planes.end(),
                 "cell " << i << ": two facets on one plane");
  std::sort(directed.begin(), directed.end());
  LINESURF_CHECK(std::adjacent_find(directed.begin(), directed.end()) == directed.end(),
                 "cell " << i << ": a directed edge is used twice");
  for (const auto& [a, b] : directed) {
    LINESURF_CHECK(std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a)),
                   "cell " << i << ": not closed at edge " << a.index() << "-" << b.index());
  }
  const auto vertices = CellVertices(cx, c);
  const std::size_t num_edges = directed.size() / 2;
  LINESURF_CHECK(vertices.size() + fs.size() == num_edges + 2,
                 "cell " << i << ": V - E + F = "
                         << static_cast<long>(vertices.size()) - static_cast<long>(num_edges) +
                                static_cast<long>(fs.size()));
  return vertices;
}

/// Cell `c` is convex, exactly: every vertex on the inner side of every facet plane, and some
/// strictly inside.
void CheckCellConvex(const CellComplex& cx, CellId c, const std::vector<VertexId>& vertices) {
  const std::size_t i = c.index();
  for (const FacetId f : cx.cell_facets[c]) {
    const int inside = cx.facet_positive_cell[f] == c ? 1 : -1;
    bool strictly_inside_seen = false;
    for (const VertexId v : vertices) {
      const int s = SignAt(cx, v, cx.facet_plane[f]);
      LINESURF_CHECK(s != -inside, "cell " << i << ": not convex at facet " << f.index());
      strictly_inside_seen |= s == inside;
    }
    LINESURF_CHECK(strictly_inside_seen, "cell " << i << ": flat");
  }
}

/// Edge `e`: at least 2 facets in cyclic (or boundary chain) order, each listing it, with its
/// cells between consecutive facets.
void CheckEdge(const CellComplex& cx, EdgeId e) {
  const std::size_t i = e.index();
  const auto fs = cx.edge_facets[e];
  const auto cs = cx.edge_cells[e];
  LINESURF_CHECK(fs.size() >= 2, "edge " << i << ": fewer than 2 facets");
  const bool boundary = cx.IsBoxFacet(fs.front());
  LINESURF_CHECK(cs.size() + (boundary ? 1 : 0) == fs.size(), "edge " << i << ": cell count");
  for (std::size_t k = 0; k < fs.size(); ++k) {
    const auto fe = cx.facet_edges[fs[k]];
    LINESURF_CHECK(std::count(fe.begin(), fe.end(), e) == 1,
                   "edge " << i << ": facet " << fs[k].index() << " lacks it");
    if (k < cs.size()) {
      const FacetId next = fs[(k + 1) % fs.size()];
      for (const FacetId g : {fs[k], next}) {
        LINESURF_CHECK(cx.facet_positive_cell[g] == cs[k] || cx.facet_negative_cell[g] == cs[k],
                       "edge " << i << ": cell " << k << " not between its facets");
      }
    }
  }
  if (boundary) LINESURF_CHECK(cx.IsBoxFacet(fs.back()), "edge " << i << ": open chain end");
}

void Check(const CellComplex& cx) {
  CheckSizes(cx);
  CheckVertices(cx);
  for (std::size_t i = 0; i < cx.NumFacets(); ++i) CheckFacet(cx, FacetId(i));
  std::vector<std::pair<VertexId, VertexId>> directed;
  std::vector<ComplexPlaneId> planes;
  for (std::size_t i = 0; i < cx.NumCells(); ++i) {
    const std::vector<VertexId> vertices = CheckCellSurface(cx, CellId(i), directed, planes);
    CheckCellConvex(cx, CellId(i), vertices);
  }
  for (std::size_t i = 0; i < cx.NumEdges(); ++i) CheckEdge(cx, EdgeId(i));
}

#undef LINESURF_CHECK

}  // namespace

Status ValidateCellComplex(const CellComplex& complex) noexcept {
  return CatchAll(kValidateCellComplexStage, [&] { Check(complex); });
}

}  // namespace linesurf::partition
