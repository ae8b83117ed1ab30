#pragma once
// Point location and straight walks in a CellComplex, with exact side tests.
//
// Tie rule (points on planes): a point p is located as the symbolically perturbed point
//   p + e*d1 + e^2*d2 + ... + e^k*dk + e^(k+1)*(1,0,0) + e^(k+2)*(0,1,0) + e^(k+3)*(0,0,1)
// for an infinitesimal e > 0, where d1..dk are the caller's tie directions. So the side of a
// plane n.x + d = 0 is sign(n.p + d); when that is 0, the first nonzero of sign(n.d1), ...,
// sign(n.dk), sign(n_x), sign(n_y), sign(n_z). Every decision is exact; every point inside the
// closed box has exactly one cell. Examples: the cell behind a segment lying on a plane, seen
// from viewpoint o: Locate(q, {q - o}); the cell on sides (s1, s2) of a structural edge of
// planes n1, n2: Locate(q, {s1*n1 + s2*n2}).
//
// Thread-safe: all methods are const and keep no caches; many threads may share one locator.

#include "engine/core/cell_complex.h"

#include <functional>
#include <span>
#include <vector>

namespace linesurf::partition {

class CellLocator {
 public:
  /// The complex must outlive the locator.
  explicit CellLocator(const CellComplex& complex);

  /// The cell containing the (perturbed) point, or an invalid id when it lies outside the box.
  /// Walks from `start` (any cell; cell 0 when invalid), crossing one plane whose side differs at
  /// a time, so it takes at most as many steps as there are planes.
  [[nodiscard]] CellId Locate(const Vec3& p,
                              std::span<const Vec3> tie_directions = {},
                              CellId start = CellId()) const;

  /// The perturbed side (+1/-1) of point p with respect to complex plane `plane` (never 0).
  [[nodiscard]] int Side(const Vec3& p,
                         ComplexPlaneId plane,
                         std::span<const Vec3> tie_directions = {}) const;

  /// Called for each facet crossed, with the segment parameter t in [0, 1] of the crossing.
  using SegmentVisitor = std::function<void(FacetId crossed, double t)>;

  /// Walks the straight segment from `from` (in from_cell) to `to` (in to_cell), calling `visit`
  /// for every facet crossed, in order of t. The walk crosses only planes that separate
  /// from_cell and to_cell, each exactly once, so it always terminates (at most one step per
  /// plane; twice that if `to` does not lie in the closure of to_cell) and always ends in
  /// to_cell. Crossing order uses double parameters; ties (the
  /// segment through an edge or a vertex) are broken by the smaller plane id among the planes
  /// the current cell can cross. Both cells must be valid.
  void WalkSegment(const Vec3& from,
                   CellId from_cell,
                   const Vec3& to,
                   CellId to_cell,
                   const SegmentVisitor& visit) const;

  /// Walks the straight segment from `from` (in from_cell) towards `to` perturbed by the tie
  /// directions (the rule of Locate) and returns the cell holding that perturbed point, calling
  /// `visit` for every facet crossed on the way, as WalkSegment does. The perturbed point must
  /// lie in the box. Same cost as WalkSegment; saves the Locate of the end cell.
  CellId WalkToPoint(const Vec3& from,
                     CellId from_cell,
                     const Vec3& to,
                     std::span<const Vec3> tie_directions,
                     const SegmentVisitor& visit) const;

  [[nodiscard]] const CellComplex& complex() const { return complex_; }

 private:
  /// The side (+1/-1) of cell c with respect to the plane of its facet f.
  [[nodiscard]] int CellSide(FacetId f, CellId c) const {
    return complex_.facet_positive_cell[f] == c ? 1 : -1;
  }
  /// Crosses, in order of the segment parameter, the facets of planes on which the current
  /// cell's side differs from target(plane), until none does; returns the cell reached.
  /// `last_t` is the parameter of the previous crossing (crossings are reported in
  /// non-decreasing t).
  template <typename Target>
  CellId WalkTowards(const Vec3& from,
                     CellId c,
                     const Vec3& to,
                     Target&& target,
                     const SegmentVisitor& visit,
                     double& last_t) const;
  /// The side (+1/-1) of cell c with respect to any plane (exact, from a cell vertex off it).
  [[nodiscard]] int CellPlaneSide(CellId c, ComplexPlaneId plane) const;

  const CellComplex& complex_;
};

}  // namespace linesurf::partition
