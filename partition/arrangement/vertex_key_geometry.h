#pragma once
// Exact tests on vertices named by global plane triples (VertexKey) of the block complexes
// (docs/design/block_engine.md, section 6): one point may carry different triples in different
// facets or blocks, so the stitch decides coincidence, order along an edge and the order of
// faces around an edge by the signs of planes at vertices, never by coordinates.

#include "partition/arrangement/block_complexes.h"

#include <cstdint>
#include <span>
#include <vector>

namespace linesurf::partition {

/// The global key of vertex `v` of a block's complex (its canonical triple, mapped and sorted).
[[nodiscard]] VertexKey BlockVertexKey(const BlockComplex& block, VertexId v);

/// true when some plane of the triple is a block face: only such vertices lie on block faces
/// (a block's canonical triple of a vertex on its boundary holds a box plane).
[[nodiscard]] bool OnSomeBlockFace(const VertexKey& v);

/// The exact sign of plane `plane` at vertex `v`.
[[nodiscard]] int SignAtVertex(const BlockComplexes& cx, const VertexKey& v, PlaneKey plane);

/// true when the two triples name the same point (each plane of `b` passes through `a`).
[[nodiscard]] bool SamePoint(const BlockComplexes& cx, const VertexKey& a, const VertexKey& b);

/// A segment from u to v (distinct points) on the line of planes p and q.
struct KeySegment {
  VertexKey u;
  VertexKey v;
  PlaneKey p;
  PlaneKey q;
};

/// true when `w` (a point other than u and v) lies on the segment, strictly between its ends.
[[nodiscard]] bool StrictlyInside(const BlockComplexes& cx,
                                  const KeySegment& s,
                                  const VertexKey& w);

/// Sorts points strictly inside the segment from u towards v.
void SortAlong(const BlockComplexes& cx, const KeySegment& s, std::vector<VertexKey>& points);

/// A face around an edge: its outward normal (exact doubles) and +1 when its cycle runs along the
/// edge from u to v, -1 from v to u.
struct EdgeFace {
  Vec3 normal = Vec3::Zero();
  int direction = 1;
};

/// The faces around the segment in counter-clockwise order about the direction u -> v, starting
/// at faces[0], as indices into `faces`. Throws kInternal when two faces leave the edge in the
/// same direction (overlapping faces).
[[nodiscard]] std::vector<std::uint32_t> OrderAroundEdge(const BlockComplexes& cx,
                                                         const KeySegment& s,
                                                         std::span<const EdgeFace> faces);

}  // namespace linesurf::partition
