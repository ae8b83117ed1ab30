#include "partition/arrangement/build_cell_complex.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "partition/arrangement/exact_predicates.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <unordered_map>

namespace linesurf::partition {
namespace {

constexpr char kBuildCellComplexStage[] = "cell_complex";
/// Cells visited between two cancellation polls inside one plane insertion.
constexpr std::uint32_t kCancelPollCells = 4096;

/// The arrangement while it is built: plain vectors, one small vector per element.
class Builder {
 public:
  Builder(const Box3& box, ExactCounter* counter) : counter_(counter) { InitBox(box); }

  std::vector<Eigen::Vector4d> planes;  // complex planes: 6 box faces, then inserted planes

  /// Splits every cell `pid` crosses; polls `ctx` every kCancelPollCells cells (one late
  /// insertion on Andalusian takes over a second). A cancelled builder is discarded.
  void Insert(std::uint32_t pid, const RunContext& ctx);
  [[nodiscard]] std::size_t NumCells() const { return cell_facets_.size(); }
  CellComplex Finish(const Box3& box, const std::vector<PlaneId>& sources);

 private:
  struct FacetSplit {
    std::uint32_t stamp = 0;
    std::uint32_t minus = 0;  // facet id of the negative piece
  };

  void InitBox(const Box3& box);
  int Sign(std::uint32_t v);
  std::uint32_t EdgeVertex(std::uint32_t u, std::uint32_t v);
  void SplitFacet(std::uint32_t f);
  void SplitCell(std::uint32_t c);
  void UpdateCellBounds(std::uint32_t c);
  std::uint32_t AddVertex(const std::array<std::uint32_t, 3>& def, std::vector<std::uint32_t> on);
  void AssignColours(CellComplex& cx);
  // The phases of Finish.
  void FinishVertices(CellComplex& cx);
  void FinishFacetsAndEdges(CellComplex& cx);
  void OrderEdgeStars(CellComplex& cx);
  void FinishCells(CellComplex& cx);

  ExactCounter* counter_;
  std::uint32_t pid_ = 0;    // plane being inserted
  std::uint32_t stamp_ = 0;  // 1 + number of insertions so far

  // Vertices.
  std::vector<std::array<std::uint32_t, 3>> vertex_def_;
  std::vector<Vec3> vertex_lo_, vertex_hi_, vertex_approx_;
  std::vector<std::vector<std::uint32_t>> vertex_on_;  // sorted planes through the vertex
  std::vector<std::uint32_t> sign_stamp_;
  std::vector<std::int8_t> sign_;

  // Facets.
  std::vector<std::vector<std::uint32_t>> facet_cycle_;
  std::vector<std::uint32_t> facet_plane_;
  std::vector<CellId> facet_pos_, facet_neg_;  ///< invalid negative cell: outside the box
  std::vector<FacetSplit> facet_split_;

  // Cells.
  std::vector<std::vector<std::uint32_t>> cell_facets_;
  std::vector<Vec3> cell_lo_, cell_hi_;

  std::unordered_map<std::uint64_t, std::uint32_t> edge_memo_;  // lookup only, never iterated
};

std::uint32_t Builder::AddVertex(const std::array<std::uint32_t, 3>& def,
                                 std::vector<std::uint32_t> on) {
  const VertexBounds b =
      ComputeVertexBounds(planes[def[0]], planes[def[1]], planes[def[2]], counter_);
  const auto id = static_cast<std::uint32_t>(vertex_def_.size());
  vertex_def_.push_back(def);
  vertex_lo_.push_back(b.lo);
  vertex_hi_.push_back(b.hi);
  vertex_approx_.push_back(b.approx);
  vertex_on_.push_back(std::move(on));
  sign_stamp_.push_back(0);
  sign_.push_back(0);
  return id;
}

void Builder::InitBox(const Box3& box) {
  planes = {Eigen::Vector4d(1, 0, 0, -box.min.x()),
            Eigen::Vector4d(0, 1, 0, -box.min.y()),
            Eigen::Vector4d(0, 0, 1, -box.min.z()),
            Eigen::Vector4d(-1, 0, 0, box.max.x()),
            Eigen::Vector4d(0, -1, 0, box.max.y()),
            Eigen::Vector4d(0, 0, -1, box.max.z())};
  for (std::uint32_t v = 0; v < 8; ++v) {
    const std::uint32_t ix = v & 1, iy = (v >> 1) & 1, iz = (v >> 2) & 1;
    std::array<std::uint32_t, 3> def{ix != 0 ? 3u : 0u, iy != 0 ? 4u : 1u, iz != 0 ? 5u : 2u};
    std::sort(def.begin(), def.end());
    AddVertex(def, {def.begin(), def.end()});
  }
  facet_cycle_ = {
      {0, 2, 6, 4}, {0, 4, 5, 1}, {0, 1, 3, 2}, {1, 5, 7, 3}, {2, 3, 7, 6}, {4, 6, 7, 5}};
  for (std::uint32_t f = 0; f < 6; ++f) {
    facet_plane_.push_back(f);
    facet_pos_.emplace_back(0u);
    facet_neg_.push_back(CellId::Invalid());
    facet_split_.push_back({});
  }
  cell_facets_ = {{0, 1, 2, 3, 4, 5}};
  cell_lo_ = {box.min};
  cell_hi_ = {box.max};
}

int Builder::Sign(std::uint32_t v) {
  if (sign_stamp_[v] == stamp_) return sign_[v];
  const Eigen::Vector4d& p = planes[pid_];
  int s = FilteredBoxSide(p, vertex_lo_[v], vertex_hi_[v]);
  if (s == 0) {
    const auto& d = vertex_def_[v];
    s = ExactSignAtVertex(planes[d[0]], planes[d[1]], planes[d[2]], p, counter_);
    if (s == 0) vertex_on_[v].push_back(pid_);  // pid_ exceeds every plane already listed
  }
  sign_stamp_[v] = stamp_;
  sign_[v] = static_cast<std::int8_t>(s);
  return s;
}

std::uint32_t Builder::EdgeVertex(std::uint32_t u, std::uint32_t v) {
  const std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | std::max(u, v);
  const auto it = edge_memo_.find(key);
  if (it != edge_memo_.end()) return it->second;
  std::vector<std::uint32_t> on;
  std::set_intersection(vertex_on_[u].begin(),
                        vertex_on_[u].end(),
                        vertex_on_[v].begin(),
                        vertex_on_[v].end(),
                        std::back_inserter(on));
  LINESURF_ASSERT(on.size() >= 2);
  const std::array<std::uint32_t, 3> def{on[0], on[1], pid_};
  on.push_back(pid_);
  const std::uint32_t w = AddVertex(def, std::move(on));
  sign_stamp_[w] = stamp_;
  sign_[w] = 0;
  edge_memo_.emplace(key, w);
  return w;
}

void Builder::SplitFacet(std::uint32_t f) {
  const std::vector<std::uint32_t> cycle = facet_cycle_[f];
  const std::size_t n = cycle.size();
  auto at = [&](std::size_t i) { return cycle[i % n]; };
  // Start of the positive run: a positive vertex whose predecessor is not positive.
  std::size_t i0 = 0;
  while (!(sign_[at(i0)] > 0 && sign_[at(i0 + n - 1)] <= 0)) {
    ++i0;
    LINESURF_ASSERT(i0 < n);
  }
  const std::uint32_t before = at(i0 + n - 1);
  const std::uint32_t t1 = sign_[before] == 0 ? before : EdgeVertex(before, at(i0));
  std::vector<std::uint32_t> plus{t1};
  std::size_t j = i0;
  while (sign_[at(j)] > 0) plus.push_back(at(j++));
  std::vector<std::uint32_t> minus;
  std::uint32_t t2 = 0;
  if (sign_[at(j)] == 0) {
    t2 = at(j);
    ++j;
  } else {
    t2 = EdgeVertex(at(j - 1), at(j));
  }
  plus.push_back(t2);
  minus.push_back(t2);
  for (; j < i0 + n; ++j) {
    const std::uint32_t v = at(j);
    if (sign_[v] < 0) minus.push_back(v);
    LINESURF_ASSERT(sign_[v] < 0 || v == before);
  }
  minus.push_back(t1);

  const auto fm = static_cast<std::uint32_t>(facet_cycle_.size());
  facet_cycle_[f] = std::move(plus);
  facet_cycle_.push_back(std::move(minus));
  facet_plane_.push_back(facet_plane_[f]);
  facet_pos_.push_back(facet_pos_[f]);
  facet_neg_.push_back(facet_neg_[f]);
  facet_split_.push_back({});
  facet_split_[f] = {stamp_, fm};
}

void Builder::UpdateCellBounds(std::uint32_t c) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const std::uint32_t f : cell_facets_[c]) {
    for (const std::uint32_t v : facet_cycle_[f]) {
      lo = lo.cwiseMin(vertex_lo_[v]);
      hi = hi.cwiseMax(vertex_hi_[v]);
    }
  }
  cell_lo_[c] = lo;
  cell_hi_[c] = hi;
}

void Builder::SplitCell(std::uint32_t c) {
  std::vector<std::uint32_t> plus_facets, minus_facets;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ring;  // new facet edges, stored direction
  auto add_ring = [&](std::uint32_t a, std::uint32_t b) {
    const std::pair<std::uint32_t, std::uint32_t> e{a, b};
    if (std::find(ring.begin(), ring.end(), e) == ring.end()) ring.push_back(e);
  };
  for (const std::uint32_t f : cell_facets_[c]) {
    const bool c_is_positive = facet_pos_[f] == CellId(c);
    if (facet_split_[f].stamp == stamp_) {
      // Mixed facet, already split (by this cell or its neighbour). The cut edge of the positive
      // piece runs t2 -> t1 in stored order; seen outward from c it is reversed when c is the
      // positive cell. The new facet runs along the outward direction of the positive piece.
      const auto& plus = facet_cycle_[f];
      const std::uint32_t t1 = plus.front(), t2 = plus.back();
      if (c_is_positive) {
        add_ring(t1, t2);
      } else {
        add_ring(t2, t1);
      }
      plus_facets.push_back(f);
      minus_facets.push_back(facet_split_[f].minus);
      continue;
    }
    bool has_pos = false, has_neg = false;
    for (const std::uint32_t v : facet_cycle_[f]) {
      has_pos |= sign_[v] > 0;
      has_neg |= sign_[v] < 0;
    }
    LINESURF_ASSERT(has_pos || has_neg);
    if (has_pos && has_neg) {
      SplitFacet(f);
      const auto& plus = facet_cycle_[f];
      if (c_is_positive) {
        add_ring(plus.front(), plus.back());
      } else {
        add_ring(plus.back(), plus.front());
      }
      plus_facets.push_back(f);
      minus_facets.push_back(facet_split_[f].minus);
      continue;
    }
    (has_pos ? plus_facets : minus_facets).push_back(f);
    // Edges of this facet lying on the plane bound the new facet. Stored direction a -> b is the
    // outward direction when c is the negative cell; positive-side facets give the outward
    // direction, negative-side ones its reverse.
    const auto& cycle = facet_cycle_[f];
    const std::size_t n = cycle.size();
    const bool keep = (has_pos != c_is_positive);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t a = cycle[i], b = cycle[(i + 1) % n];
      if (sign_[a] == 0 && sign_[b] == 0) {
        if (keep) {
          add_ring(a, b);
        } else {
          add_ring(b, a);
        }
      }
    }
  }
  // Chain the ring combinatorially.
  LINESURF_ASSERT(ring.size() >= 3);
  std::vector<std::uint32_t> cycle;
  cycle.reserve(ring.size());
  std::uint32_t cur = ring.front().first;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    cycle.push_back(cur);
    const auto it =
        std::find_if(ring.begin(), ring.end(), [&](const auto& e) { return e.first == cur; });
    LINESURF_ASSERT(it != ring.end());
    cur = it->second;
  }
  LINESURF_ASSERT(cur == cycle.front());

  const auto cm = static_cast<std::uint32_t>(cell_facets_.size());
  const auto nf = static_cast<std::uint32_t>(facet_cycle_.size());
  facet_cycle_.push_back(std::move(cycle));
  facet_plane_.push_back(pid_);
  facet_pos_.emplace_back(c);
  facet_neg_.emplace_back(cm);
  facet_split_.push_back({});
  for (const std::uint32_t f : minus_facets) {
    if (facet_pos_[f] == CellId(c)) facet_pos_[f] = CellId(cm);
    if (facet_neg_[f] == CellId(c)) facet_neg_[f] = CellId(cm);
  }
  plus_facets.push_back(nf);
  minus_facets.push_back(nf);
  cell_facets_[c] = std::move(plus_facets);
  cell_facets_.push_back(std::move(minus_facets));
  cell_lo_.emplace_back();
  cell_hi_.emplace_back();
  UpdateCellBounds(c);
  UpdateCellBounds(cm);
}

void Builder::Insert(std::uint32_t pid, const RunContext& ctx) {
  pid_ = pid;
  ++stamp_;
  edge_memo_.clear();
  const std::size_t num_cells = cell_facets_.size();
  for (std::uint32_t c = 0; c < num_cells; ++c) {
    if (c % kCancelPollCells == kCancelPollCells - 1) ctx.ThrowIfCancelled(kBuildCellComplexStage);
    if (FilteredBoxSide(planes[pid], cell_lo_[c], cell_hi_[c]) != 0) continue;
    bool has_pos = false, has_neg = false;
    for (const std::uint32_t f : cell_facets_[c]) {
      for (const std::uint32_t v : facet_cycle_[f]) {
        const int s = Sign(v);
        has_pos |= s > 0;
        has_neg |= s < 0;
      }
      if (facet_split_[f].stamp == stamp_) {
        for (const std::uint32_t v : facet_cycle_[facet_split_[f].minus]) {
          const int s = Sign(v);
          has_pos |= s > 0;
          has_neg |= s < 0;
        }
      }
    }
    if (has_pos && has_neg) SplitCell(c);
  }
}

/// colour = +1 when an even number of non-box planes have the cell on their positive side, -1
/// otherwise: the parity of cell 0 from its vertices, then flipped across every inner facet.
void Builder::AssignColours(CellComplex& cx) {
  const std::size_t nc = cx.NumCells();
  cx.cell_colour = IdVector<CellId, std::int8_t>(nc, 0);
  if (nc == 0) return;
  const CellId c0(std::uint32_t{0});
  std::vector<std::uint32_t> vertices;
  for (const FacetId f : cx.cell_facets[c0]) {
    for (const VertexId v : cx.facet_vertices[f]) vertices.push_back(v.value());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  int parity = 0;
  for (std::uint32_t p = kNumBoxPlanes; p < planes.size(); ++p) {
    int side = 0;
    for (std::size_t i = 0; i < vertices.size() && side == 0; ++i) {
      const std::uint32_t v = vertices[i];
      if (std::binary_search(vertex_on_[v].begin(), vertex_on_[v].end(), p)) continue;
      const auto& d = vertex_def_[v];
      side = ExactSignAtVertex(planes[d[0]], planes[d[1]], planes[d[2]], planes[p], counter_);
    }
    LINESURF_ASSERT(side != 0);
    parity ^= side > 0 ? 1 : 0;
  }
  cx.cell_colour[c0] = parity != 0 ? std::int8_t{-1} : std::int8_t{1};
  std::vector<CellId> queue{c0};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellId c = queue[head];
    for (const FacetId f : cx.cell_facets[c]) {
      const CellId d = cx.Neighbour(f, c);
      if (!d.IsValid() || cx.cell_colour[d] != 0) continue;
      cx.cell_colour[d] = static_cast<std::int8_t>(-cx.cell_colour[c]);
      queue.push_back(d);
    }
  }
}

CellComplex Builder::Finish(const Box3& box, const std::vector<PlaneId>& sources) {
  CellComplex cx;
  cx.box = box;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    ComplexPlane plane;
    plane.coefficients = planes[p];
    plane.source = p < kNumBoxPlanes ? PlaneId() : sources[p - kNumBoxPlanes];
    cx.planes.push_back(plane);
  }
  FinishVertices(cx);
  FinishFacetsAndEdges(cx);
  OrderEdgeStars(cx);
  FinishCells(cx);
  AssignColours(cx);
  return cx;
}

/// Vertices: rounded points and canonical triples.
void Builder::FinishVertices(CellComplex& cx) {
  const std::size_t nv = vertex_def_.size();
  cx.vertex_points.resize(nv);
  cx.vertex_planes.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    cx.vertex_points[VertexId(v)] = vertex_approx_[v];
    const auto& on = vertex_on_[v];
    std::array<std::uint32_t, 3> best = vertex_def_[v];
    std::sort(best.begin(), best.end());
    bool found = false;
    for (std::size_t i = 0; i < on.size() && !found; ++i) {
      for (std::size_t j = i + 1; j < on.size() && !found; ++j) {
        for (std::size_t k = j + 1; k < on.size() && !found; ++k) {
          const std::array<std::uint32_t, 3> t{on[i], on[j], on[k]};
          if (t > best) break;
          if (t == best || ExactSignDet3(planes[t[0]].head<3>(),
                                         planes[t[1]].head<3>(),
                                         planes[t[2]].head<3>(),
                                         counter_) != 0) {
            best = t;
            found = true;
          }
        }
      }
    }
    cx.vertex_planes[VertexId(v)] = {
        ComplexPlaneId(best[0]), ComplexPlaneId(best[1]), ComplexPlaneId(best[2])};
  }
}

/// Facets with their cells and vertices, the edges (sorted vertex pairs) and facet -> edges.
void Builder::FinishFacetsAndEdges(CellComplex& cx) {
  const std::size_t nfac = facet_cycle_.size();
  std::vector<std::uint64_t> edge_keys;
  for (std::size_t f = 0; f < nfac; ++f) {
    const auto& cyc = facet_cycle_[f];
    cx.facet_plane.push_back(ComplexPlaneId(facet_plane_[f]));
    cx.facet_positive_cell.push_back(facet_pos_[f]);
    cx.facet_negative_cell.push_back(facet_neg_[f]);
    std::vector<VertexId> ids;
    ids.reserve(cyc.size());
    for (std::size_t i = 0; i < cyc.size(); ++i) {
      ids.emplace_back(cyc[i]);
      const std::uint32_t a = cyc[i], b = cyc[(i + 1) % cyc.size()];
      edge_keys.push_back((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b));
    }
    cx.facet_vertices.AddRow(ids);
  }
  std::vector<std::uint64_t> facet_edge_keys = edge_keys;
  std::sort(edge_keys.begin(), edge_keys.end());
  edge_keys.erase(std::unique(edge_keys.begin(), edge_keys.end()), edge_keys.end());
  for (const std::uint64_t key : edge_keys) {
    cx.edge_vertices.push_back({VertexId(static_cast<std::uint32_t>(key >> 32)),
                                VertexId(static_cast<std::uint32_t>(key & 0xffffffffu))});
  }
  // facet -> edges, and edge -> incident facets (in facet order).
  std::vector<std::uint32_t> facet_edge_ids(facet_edge_keys.size());
  for (std::size_t i = 0; i < facet_edge_keys.size(); ++i) {
    const auto e = static_cast<std::uint32_t>(
        std::lower_bound(edge_keys.begin(), edge_keys.end(), facet_edge_keys[i]) -
        edge_keys.begin());
    facet_edge_ids[i] = e;
  }
  {
    std::size_t k = 0;
    for (std::size_t f = 0; f < nfac; ++f) {
      std::vector<EdgeId> row;
      for (std::size_t i = 0; i < facet_cycle_[f].size(); ++i)
        row.emplace_back(facet_edge_ids[k++]);
      cx.facet_edges.AddRow(row);
    }
  }
}

/// The facets and cells around every edge, in cyclic order.
void Builder::OrderEdgeStars(CellComplex& cx) {
  const std::size_t ne = cx.edge_vertices.size();
  const Csr<EdgeId, FacetId> incident = cx.facet_edges.Transpose(ne);
  // Cyclic order around each edge by walking cell -> other facet containing the edge.
  std::vector<FacetId> ordered_facets;
  std::vector<CellId> ordered_cells;
  std::vector<std::uint32_t> fs;  // the facets of the edge, as the plain indices used below
  for (std::size_t e = 0; e < ne; ++e) {
    fs.clear();
    for (const FacetId f : incident[EdgeId(e)]) fs.push_back(f.value());
    ordered_facets.clear();
    ordered_cells.clear();
    FacetId start;
    bool boundary = false;
    for (const std::uint32_t f : fs) {
      if (facet_plane_[f] < kNumBoxPlanes) {
        boundary = true;
        start = std::min(start, FacetId(f));  // the invalid id is above every facet
      }
    }
    if (!boundary) start = FacetId(*std::min_element(fs.begin(), fs.end()));
    std::uint32_t f = start.value();
    CellId cell = facet_pos_[f];
    for (std::size_t step = 0; step <= fs.size(); ++step) {
      ordered_facets.emplace_back(f);
      if (boundary && step > 0 && facet_plane_[f] < kNumBoxPlanes) break;
      ordered_cells.emplace_back(cell);
      FacetId next;
      for (const std::uint32_t g : fs) {
        if (g != f && (facet_pos_[g] == cell || facet_neg_[g] == cell)) {
          next = FacetId(g);
          break;
        }
      }
      LINESURF_ASSERT(next.IsValid());
      if (!boundary && next == start) break;
      f = next.value();
      cell = facet_pos_[f] == cell ? facet_neg_[f] : facet_pos_[f];
    }
    LINESURF_ASSERT(ordered_facets.size() == fs.size());
    cx.edge_facets.AddRow(ordered_facets);
    cx.edge_cells.AddRow(ordered_cells);
  }
}

void Builder::FinishCells(CellComplex& cx) {
  for (std::size_t c = 0; c < cell_facets_.size(); ++c) {
    std::vector<FacetId> row;
    row.reserve(cell_facets_[c].size());
    for (const std::uint32_t f : cell_facets_[c]) row.emplace_back(f);
    cx.cell_facets.AddRow(row);
  }
}

bool IsUsablePlane(const Plane3& plane) {
  return plane.point.allFinite() && plane.normal.allFinite() && plane.normal.squaredNorm() > 0 &&
         std::isfinite(plane.Offset());
}

CellComplexResult BuildOne(const Box3& box,
                           std::span<const Plane3> input,
                           const CellComplexOptions& options,
                           const RunContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  LINESURF_THROW_IF(box.IsEmpty() || !box.min.allFinite() || !box.max.allFinite() ||
                        !(box.min.array() < box.max.array()).all(),
                    kInvalidInput,
                    kBuildCellComplexStage,
                    "the box must be finite with min < max on every axis");
  CellComplexResult result;
  CellComplexStats& stats = result.stats;
  stats.planes_input = input.size();
  ExactCounter counter;
  Builder builder(box, &counter);

  const double diagonal = box.Extent().norm();
  if (box.Center().norm() > options.max_centre_offset_in_diagonals * diagonal) {
    std::ostringstream msg;
    msg << "box centre lies " << box.Center().norm() / diagonal
        << " diagonals from the origin: recentre to a local frame for speed";
    result.warnings.push_back(msg.str());
  }
  std::array<Vec3, 8> corners;
  for (int v = 0; v < 8; ++v) {
    corners[v] = Vec3((v & 1) != 0 ? box.max.x() : box.min.x(),
                      (v & 2) != 0 ? box.max.y() : box.min.y(),
                      (v & 4) != 0 ? box.max.z() : box.min.z());
  }
  std::vector<PlaneId> sources;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!IsUsablePlane(input[i])) {
      ++stats.planes_invalid;
      continue;
    }
    const Eigen::Vector4d p(
        input[i].normal.x(), input[i].normal.y(), input[i].normal.z(), input[i].Offset());
    int num_pos = 0, num_neg = 0;
    for (const Vec3& corner : corners) {
      const int s = ExactSignAtPoint(p, corner, &counter);
      num_pos += s > 0;
      num_neg += s < 0;
    }
    if (num_pos == 8 || num_neg == 8) {
      ++stats.planes_skipped_outside;
      continue;
    }
    if (num_pos == 0 || num_neg == 0) {
      ++stats.planes_skipped_touching;
      continue;
    }
    bool duplicate = false;
    for (std::size_t q = kNumBoxPlanes; q < builder.planes.size() && !duplicate; ++q) {
      duplicate = ExactProportionality(p, builder.planes[q], &counter) != 0;
    }
    if (duplicate) {
      ++stats.planes_duplicate;
      continue;
    }
    builder.planes.push_back(p);
    sources.emplace_back(i);
  }
  stats.planes_used = sources.size();
  auto add_warning = [&](std::size_t n, const char* what) {
    if (n > 0) result.warnings.push_back(std::to_string(n) + " planes skipped: " + what);
  };
  add_warning(stats.planes_invalid, "non-finite or zero normal");
  add_warning(stats.planes_skipped_outside, "miss the box");
  add_warning(stats.planes_skipped_touching, "only touch the box");
  add_warning(stats.planes_duplicate, "same or opposite of an earlier plane");

  for (std::size_t k = 0; k < sources.size(); ++k) {
    ctx.ThrowIfCancelled(kBuildCellComplexStage);
    builder.Insert(static_cast<std::uint32_t>(kNumBoxPlanes + k), ctx);
    LINESURF_THROW_IF(
        options.max_cells > 0 && builder.NumCells() > options.max_cells,
        kResourceExhausted,
        kBuildCellComplexStage,
        "more than max_cells = " << options.max_cells << " cells after " << k + 1 << " planes");
    ctx.ReportProgress(kBuildCellComplexStage,
                       static_cast<double>(k + 1) / static_cast<double>(sources.size()));
  }
  result.complex = builder.Finish(box, sources);
  stats.exact_fallbacks = counter.exact_fallbacks.load();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

Status CellComplexOptions::Validate() const {
  if (!(max_centre_offset_in_diagonals > 0)) {
    return Error{ErrorCode::kInvalidOptions,
                 kBuildCellComplexStage,
                 "max_centre_offset_in_diagonals must be > 0"};
  }
  return {};
}

Expected<CellComplexResult> BuildCellComplex(const Box3& box,
                                             std::span<const Plane3> planes,
                                             const CellComplexOptions& options,
                                             const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  return CatchAll(kBuildCellComplexStage, [&] { return BuildOne(box, planes, options, ctx); });
}

Expected<std::vector<CellComplexResult>> BuildCellComplexes(
    std::span<const Box3> boxes,
    std::span<const std::vector<Plane3>> planes_per_box,
    const CellComplexOptions& options,
    const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  if (planes_per_box.size() != boxes.size()) {
    return Error{
        ErrorCode::kInvalidInput, kBuildCellComplexStage, "one plane list per box is required"};
  }
  return CatchAll(kBuildCellComplexStage, [&] {
    std::vector<Expected<CellComplexResult>> results(boxes.size(), Error{});
    std::size_t finished = 0;
    std::mutex progress_mutex;  // count and report together, so fractions only grow
    RunInArena(ctx, [&] {
      tbb::parallel_for(std::size_t{0}, boxes.size(), [&](std::size_t b) {
        if (ctx.ShouldStop()) {
          results[b] = Error{ErrorCode::kCancelled, kBuildCellComplexStage, "cancelled"};
          return;
        }
        results[b] = CatchAll(kBuildCellComplexStage, [&] {
          RunContext quiet;
          quiet.is_cancelled = [&ctx] { return ctx.ShouldStop(); };
          return BuildOne(boxes[b], planes_per_box[b], options, quiet);
        });
        // Progress by boxes finished: the builds themselves report nothing.
        const std::lock_guard<std::mutex> lock(progress_mutex);
        ++finished;
        ctx.ReportProgress(kBuildCellComplexStage,
                           static_cast<double>(finished) / static_cast<double>(boxes.size()));
      });
    });
    std::vector<CellComplexResult> out;
    out.reserve(boxes.size());
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      if (!results[b]) {
        Error error = results[b].error();
        error.message = "box " + std::to_string(b) + ": " + error.message;
        throw LinesurfException(error);
      }
      out.push_back(std::move(results[b]).value());
    }
    return out;
  });
}

Expected<std::vector<CellComplexResult>> BuildCellComplexes(std::span<const Box3> boxes,
                                                            std::span<const Plane3> planes,
                                                            const CellComplexOptions& options,
                                                            const RunContext& ctx) noexcept {
  const std::vector<std::vector<Plane3>> per_box(boxes.size(),
                                                 std::vector<Plane3>(planes.begin(), planes.end()));
  return BuildCellComplexes(boxes, per_box, options, ctx);
}

}  // namespace linesurf::partition
