#pragma once
// Test support: the cell complex of an nx x ny x nz grid of unit cubes in the box
// [0,nx]x[0,ny]x[0,nz], built by hand with the conventions of engine/core/cell_complex.h, so the
// pipeline's unit tests do not depend on the arrangement builder.

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "engine/core/cell_complex.h"

namespace linesurf::pipeline::testing {

class GridComplexForTest {
 public:
  GridComplexForTest(int nx, int ny, int nz) : n_{nx, ny, nz} { Build(); }

  [[nodiscard]] const CellComplex& complex() const { return cx_; }
  [[nodiscard]] CellId Cell(int i, int j, int k) const {
    return CellId(static_cast<std::size_t>(i + n_[0] * (j + n_[1] * k)));
  }
  [[nodiscard]] bool OnBox(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == n_[0] - 1 || j == n_[1] - 1 || k == n_[2] - 1;
  }

 private:
  using Idx = std::array<int, 3>;

  [[nodiscard]] bool CellExists(const Idx& c) const {
    for (int a = 0; a < 3; ++a) {
      if (c[a] < 0 || c[a] >= n_[a]) return false;
    }
    return true;
  }
  [[nodiscard]] CellId CellAt(const Idx& c) const {
    return CellExists(c) ? Cell(c[0], c[1], c[2]) : CellId::Invalid();
  }
  [[nodiscard]] VertexId VertexAt(const Idx& p) const {
    return VertexId(static_cast<std::size_t>(p[0] + (n_[0] + 1) * (p[1] + (n_[1] + 1) * p[2])));
  }
  [[nodiscard]] ComplexPlaneId PlaneAt(int axis, int pos) const {
    if (pos == 0) return ComplexPlaneId(static_cast<std::size_t>(axis));
    if (pos == n_[axis]) return ComplexPlaneId(static_cast<std::size_t>(3 + axis));
    std::size_t id = kNumBoxPlanes;
    for (int a = 0; a < axis; ++a) id += static_cast<std::size_t>(n_[a] - 1);
    return ComplexPlaneId(id + static_cast<std::size_t>(pos - 1));
  }

  void Build() {
    cx_.box.min = Vec3::Zero();
    cx_.box.max = Vec3(n_[0], n_[1], n_[2]);
    // Planes: box planes with inward normals, then internal planes x = i, y = j, z = k.
    for (int side = 0; side < 2; ++side) {
      for (int a = 0; a < 3; ++a) {
        ComplexPlane p;
        p.coefficients[a] = side == 0 ? 1.0 : -1.0;
        p.coefficients[3] = side == 0 ? 0.0 : n_[a];
        cx_.planes.push_back(p);
      }
    }
    for (int a = 0; a < 3; ++a) {
      for (int pos = 1; pos < n_[a]; ++pos) {
        ComplexPlane p;
        p.coefficients[a] = 1.0;
        p.coefficients[3] = -pos;
        cx_.planes.push_back(p);
      }
    }
    // Vertices.
    for (int k = 0; k <= n_[2]; ++k) {
      for (int j = 0; j <= n_[1]; ++j) {
        for (int i = 0; i <= n_[0]; ++i) {
          cx_.vertex_points.push_back(Vec3(i, j, k));
          std::array<ComplexPlaneId, 3> t{PlaneAt(0, i), PlaneAt(1, j), PlaneAt(2, k)};
          std::sort(t.begin(), t.end());
          cx_.vertex_planes.push_back(t);
        }
      }
    }
    // Edges along each axis a from grid point p to p + e_a.
    for (int a = 0; a < 3; ++a) {
      Idx p{};
      for (p[2] = 0; p[2] <= n_[2]; ++p[2]) {
        for (p[1] = 0; p[1] <= n_[1]; ++p[1]) {
          for (p[0] = 0; p[0] <= n_[0]; ++p[0]) {
            if (p[a] == n_[a]) continue;
            Idx q = p;
            ++q[a];
            edge_of_[{VertexAt(p).value(), VertexAt(q).value()}] = cx_.edge_vertices.NextId();
            cx_.edge_vertices.push_back({VertexAt(p), VertexAt(q)});
            edge_origin_.push_back({a, p});
          }
        }
      }
    }
    // Facets on planes normal to axis a at position pos, one per unit square.
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      const int c = (a + 2) % 3;
      for (int pos = 0; pos <= n_[a]; ++pos) {
        for (int v = 0; v < n_[c]; ++v) {
          for (int u = 0; u < n_[b]; ++u) {
            Idx lo{};
            lo[a] = pos;
            lo[b] = u;
            lo[c] = v;
            Idx below = lo;
            --below[a];
            // Plane normal: +a except the far box plane (-a).
            const bool flipped = pos == n_[a];
            const CellId above_cell = CellAt(lo);
            const CellId below_cell = CellAt(below);
            facet_of_[{a, pos, u, v}] = cx_.facet_plane.NextId();
            cx_.facet_plane.push_back(PlaneAt(a, pos));
            cx_.facet_positive_cell.push_back(flipped ? below_cell : above_cell);
            cx_.facet_negative_cell.push_back(flipped ? above_cell : below_cell);
            // Square (u,v),(u+1,v),(u+1,v+1),(u,v+1) in (b,c) has normal b x c = +a.
            std::array<Idx, 4> sq{lo, lo, lo, lo};
            ++sq[1][b];
            ++sq[2][b];
            ++sq[2][c];
            ++sq[3][c];
            if (flipped) std::reverse(sq.begin(), sq.end());
            std::array<VertexId, 4> vs{};
            std::array<EdgeId, 4> es{};
            for (int t = 0; t < 4; ++t) vs[t] = VertexAt(sq[t]);
            for (int t = 0; t < 4; ++t) {
              std::uint32_t x = vs[t].value();
              std::uint32_t y = vs[(t + 1) % 4].value();
              if (x > y) std::swap(x, y);
              es[t] = edge_of_.at({x, y});
            }
            cx_.facet_vertices.AddRow(vs);
            cx_.facet_edges.AddRow(es);
          }
        }
      }
    }
    // Edge stars: quadrants around the edge in the (b, c) plane, counter-clockwise.
    for (std::size_t e = 0; e < cx_.NumEdges(); ++e) {
      // Named, not a structured binding: clang 14 (sanitizer build) cannot capture one.
      const int a = edge_origin_[e].first;
      const auto& p = edge_origin_[e].second;
      const int b = (a + 1) % 3;
      const int c = (a + 2) % 3;
      const std::array<std::array<int, 2>, 4> quadrant_offsets{{{0, 0}, {-1, 0}, {-1, -1}, {0, -1}}};
      std::array<CellId, 4> q{};
      for (int t = 0; t < 4; ++t) {
        Idx cell = p;
        cell[b] += quadrant_offsets[t][0];
        cell[c] += quadrant_offsets[t][1];
        q[t] = CellAt(cell);
      }
      // Facet between quadrant t-1 and t: t=0: plane c at p[c], u = p[b]; t=1: plane b at p[b],
      // v = p[c]; t=2: plane c, u = p[b]-1; t=3: plane b, v = p[c]-1.
      const auto facet_between = [&](int t) {
        if (t == 0) return FacetAt(c, p[c], p[a], p[b], a, b);
        if (t == 1) return FacetAt(b, p[b], p[a], p[c], a, c);
        if (t == 2) return FacetAt(c, p[c], p[a], p[b] - 1, a, b);
        return FacetAt(b, p[b], p[a], p[c] - 1, a, c);
      };
      int start = 0;
      for (int t = 0; t < 4; ++t) {
        if (!q[(t + 3) % 4].IsValid() && q[t].IsValid()) start = t;
      }
      std::vector<FacetId> facets;
      std::vector<CellId> cells;
      for (int s = 0; s < 4; ++s) {
        const int t = (start + s) % 4;
        const bool prev_ok = q[(t + 3) % 4].IsValid();
        if (!prev_ok && !q[t].IsValid()) continue;
        facets.push_back(facet_between(t));
        if (q[t].IsValid()) {
          cells.push_back(q[t]);
        } else {
          break;  // the chain ends at the box
        }
      }
      cx_.edge_facets.AddRow(facets);
      cx_.edge_cells.AddRow(cells);
    }
    // Cells and colours.
    for (int k = 0; k < n_[2]; ++k) {
      for (int j = 0; j < n_[1]; ++j) {
        for (int i = 0; i < n_[0]; ++i) {
          std::array<FacetId, 6> fs{FacetAt(0, i, j, k, 1, 2), FacetAt(0, i + 1, j, k, 1, 2),
                                    FacetAt(1, j, k, i, 2, 0), FacetAt(1, j + 1, k, i, 2, 0),
                                    FacetAt(2, k, i, j, 0, 1), FacetAt(2, k + 1, i, j, 0, 1)};
          cx_.cell_facets.AddRow(fs);
          cx_.cell_colour.push_back(static_cast<std::int8_t>((i + j + k) % 2 == 0 ? 1 : -1));
        }
      }
    }
  }

  /// Facet on the plane normal to `axis` at `pos`; `s` and `t` are the indices of the square
  /// along axes `axis_s` and `axis_t` (any order).
  [[nodiscard]] FacetId FacetAt(int axis, int pos, int s, int t, int axis_s, int axis_t) const {
    const int b = (axis + 1) % 3;
    Idx idx{};
    idx[axis_s] = s;
    idx[axis_t] = t;
    const int c = (axis + 2) % 3;
    return facet_of_.at({axis, pos, idx[b], idx[c]});
  }

  std::array<int, 3> n_;
  CellComplex cx_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeId> edge_of_;
  std::vector<std::pair<int, Idx>> edge_origin_;
  std::map<std::array<int, 4>, FacetId> facet_of_;
};

}  // namespace linesurf::pipeline::testing
