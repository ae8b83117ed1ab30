#include "partition/arrangement/cell_locator.h"

#include "engine/core/exception.h"
#include "partition/arrangement/exact_predicates.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace linesurf::partition {

CellLocator::CellLocator(const CellComplex& complex) : complex_(complex) {}

int CellLocator::Side(const Vec3& p,
                      ComplexPlaneId plane,
                      std::span<const Vec3> tie_directions) const {
  const Eigen::Vector4d& coeffs = complex_.planes[plane].coefficients;
  const int s = ExactSignAtPoint(coeffs, p);
  if (s != 0) return s;
  const Vec3 n = coeffs.head<3>();
  for (const Vec3& d : tie_directions) {
    const int t = ExactSignDot(n, d);
    if (t != 0) return t;
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (n[axis] != 0) return n[axis] > 0 ? 1 : -1;
  }
  return 1;  // unreachable for a valid plane
}

int CellLocator::CellPlaneSide(CellId c, ComplexPlaneId plane) const {
  for (const FacetId f : complex_.cell_facets[c]) {
    if (complex_.facet_plane[f] == plane) return CellSide(f, c);
  }
  const Eigen::Vector4d& l = complex_.planes[plane].coefficients;
  for (const FacetId f : complex_.cell_facets[c]) {
    for (const VertexId v : complex_.facet_vertices[f]) {
      const auto& t = complex_.vertex_planes[v];
      if (t[0] == plane || t[1] == plane || t[2] == plane) continue;
      const int s = ExactSignAtVertex(complex_.planes[t[0]].coefficients,
                                      complex_.planes[t[1]].coefficients,
                                      complex_.planes[t[2]].coefficients,
                                      l);
      if (s != 0) return s;
    }
  }
  LINESURF_ASSERT(false);  // a cell has volume: some vertex lies off every plane
  return 0;
}

CellId CellLocator::Locate(const Vec3& p,
                           std::span<const Vec3> tie_directions,
                           CellId start) const {
  if (complex_.NumCells() == 0) return CellId();
  std::vector<std::int8_t> side(complex_.planes.size(), 0);  // 0 = not computed yet
  auto target = [&](ComplexPlaneId plane) {
    std::int8_t& s = side[plane.index()];
    if (s == 0) s = static_cast<std::int8_t>(Side(p, plane, tie_directions));
    return s;
  };
  CellId c =
      start.IsValid() && start.index() < complex_.NumCells() ? start : CellId(std::uint32_t{0});
  for (std::size_t step = 0; step <= complex_.planes.size(); ++step) {
    FacetId wrong;
    for (const FacetId f : complex_.cell_facets[c]) {
      if (target(complex_.facet_plane[f]) != CellSide(f, c)) {
        wrong = f;
        break;
      }
    }
    if (!wrong.IsValid()) return c;
    if (complex_.IsBoxFacet(wrong)) return CellId();  // outside the box
    c = complex_.Neighbour(wrong, c);
  }
  LINESURF_ASSERT(false);  // each step fixes one plane's side for good
  return CellId();
}

template <typename Target>
CellId CellLocator::WalkTowards(const Vec3& from,
                                CellId c,
                                const Vec3& to,
                                Target&& target,
                                const SegmentVisitor& visit,
                                double& last_t) const {
  auto parameter = [&](ComplexPlaneId plane) {
    const Eigen::Vector4d& l = complex_.planes[plane].coefficients;
    const double f0 = l.head<3>().dot(from) + l[3];
    const double f1 = l.head<3>().dot(to) + l[3];
    if (f0 == f1) return 0.5;
    return std::clamp(f0 / (f0 - f1), 0.0, 1.0);
  };
  // Each crossing puts one plane on its target side for good: at most one step per plane.
  for (std::size_t step = 0; step <= complex_.planes.size(); ++step) {
    FacetId best;
    double best_t = std::numeric_limits<double>::infinity();
    for (const FacetId f : complex_.cell_facets[c]) {
      const ComplexPlaneId plane = complex_.facet_plane[f];
      if (complex_.IsBoxFacet(f) || target(plane) == CellSide(f, c)) continue;
      const double t = parameter(plane);
      if (t < best_t || (t == best_t && plane < complex_.facet_plane[best])) {
        best = f;
        best_t = t;
      }
    }
    if (!best.IsValid()) return c;
    last_t = std::max(last_t, best_t);  // crossings are reported in non-decreasing t
    if (visit) visit(best, last_t);
    c = complex_.Neighbour(best, c);
  }
  LINESURF_ASSERT(false);
  return c;
}

void CellLocator::WalkSegment(const Vec3& from,
                              CellId from_cell,
                              const Vec3& to,
                              CellId to_cell,
                              const SegmentVisitor& visit) const {
  LINESURF_ASSERT(from_cell.IsValid() && to_cell.IsValid());
  // The side of to_cell for each plane: from the point `to` when it lies strictly off the plane
  // (cheap), else from the cell's vertices. Should `to` not lie in to_cell after all, a second
  // phase uses the cell's vertices only, so the walk still ends in to_cell.
  std::vector<std::int8_t> side(complex_.planes.size(), 0);
  bool cell_sides_only = false;
  auto target = [&](ComplexPlaneId plane) {
    std::int8_t& s = side[plane.index()];
    if (s == 0 && !cell_sides_only) {
      s = static_cast<std::int8_t>(ExactSignAtPoint(complex_.planes[plane].coefficients, to));
    }
    if (s == 0) s = static_cast<std::int8_t>(CellPlaneSide(to_cell, plane));
    return s;
  };
  double last_t = 0.0;
  const CellId reached = WalkTowards(from, from_cell, to, target, visit, last_t);
  if (reached == to_cell) return;
  cell_sides_only = true;
  std::fill(side.begin(), side.end(), std::int8_t{0});
  const CellId end = WalkTowards(from, reached, to, target, visit, last_t);
  LINESURF_ASSERT(end == to_cell);
}

CellId CellLocator::WalkToPoint(const Vec3& from,
                                CellId from_cell,
                                const Vec3& to,
                                std::span<const Vec3> tie_directions,
                                const SegmentVisitor& visit) const {
  LINESURF_ASSERT(from_cell.IsValid());
  std::vector<std::int8_t> side(complex_.planes.size(), 0);
  auto target = [&](ComplexPlaneId plane) {
    std::int8_t& s = side[plane.index()];
    if (s == 0) s = static_cast<std::int8_t>(Side(to, plane, tie_directions));
    return s;
  };
  double last_t = 0.0;
  return WalkTowards(from, from_cell, to, target, visit, last_t);
}

}  // namespace linesurf::partition
