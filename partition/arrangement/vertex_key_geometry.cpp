#include "partition/arrangement/vertex_key_geometry.h"

#include "engine/core/exception.h"
#include "partition/arrangement/exact_predicates.h"
#include "partition/arrangement/seam_overlay.h"

#include <algorithm>

namespace linesurf::partition {
namespace {

constexpr char kVertexKeyGeometryStage[] = "vertex_key_geometry";

/// A plane of `at` that does not pass through `other` (exists: the planes of a triple meet in
/// one point only). It crosses the line from `at` to `other` there, transversally.
PlaneKey TransversePlane(const BlockComplexes& cx, const VertexKey& at, const VertexKey& other) {
  for (const PlaneKey k : at) {
    if (SignAt(cx, other, k) != 0) return k;
  }
  LINESURF_THROW_IF(
      true, kInternal, kVertexKeyGeometryStage, "two triples of one point given as a segment");
  return {};
}

}  // namespace

VertexKey BlockVertexKey(const BlockComplex& block, VertexId v) {
  const auto& t = block.complex.vertex_planes[v];
  VertexKey key{block.plane_keys[t[0].index()],
                block.plane_keys[t[1].index()],
                block.plane_keys[t[2].index()]};
  std::sort(key.begin(), key.end());
  return key;
}

bool OnSomeBlockFace(const VertexKey& v) {
  return std::any_of(v.begin(), v.end(), [](PlaneKey k) { return k.IsFace(); });
}

int SignAtVertex(const BlockComplexes& cx, const VertexKey& v, PlaneKey plane) {
  return SignAt(cx, v, plane);
}

bool SamePoint(const BlockComplexes& cx, const VertexKey& a, const VertexKey& b) {
  return std::all_of(b.begin(), b.end(), [&](PlaneKey k) { return SignAt(cx, a, k) == 0; });
}

bool StrictlyInside(const BlockComplexes& cx, const KeySegment& s, const VertexKey& w) {
  if (SignAt(cx, w, s.p) != 0 || SignAt(cx, w, s.q) != 0) return false;
  const PlaneKey at_u = TransversePlane(cx, s.u, s.v);
  const PlaneKey at_v = TransversePlane(cx, s.v, s.u);
  return SignAt(cx, w, at_u) == SignAt(cx, s.v, at_u) &&
         SignAt(cx, w, at_v) == SignAt(cx, s.u, at_v);
}

void SortAlong(const BlockComplexes& cx, const KeySegment& s, std::vector<VertexKey>& points) {
  // a comes before b when b lies on v's side of a plane through a crossing the line.
  std::sort(points.begin(), points.end(), [&](const VertexKey& a, const VertexKey& b) {
    if (a == b) return false;
    const PlaneKey at_a = TransversePlane(cx, a, s.v);
    return SignAt(cx, b, at_a) == SignAt(cx, s.v, at_a);
  });
}

std::vector<std::uint32_t> OrderAroundEdge(const BlockComplexes& cx,
                                           const KeySegment& s,
                                           std::span<const EdgeFace> faces) {
  const Vec3 p = cx.Coefficients(s.p).head<3>();
  const Vec3 q = cx.Coefficients(s.q).head<3>();
  // l = p x q; lambda = +1 when l points from u to v: a plane U through u crossing the line has
  // U(v) = lambda * |v - u| / |l| * (n_U . l), and n_U . l = det[n_U; p; q].
  const PlaneKey at_u = TransversePlane(cx, s.u, s.v);
  const int lambda = SignAt(cx, s.v, at_u) * ExactSignDet3(cx.Coefficients(at_u).head<3>(), p, q);
  LINESURF_THROW_IF(
      lambda == 0, kInternal, kVertexKeyGeometryStage, "edge planes do not meet in a line");
  // The direction of face f into itself, perpendicular to the edge, is
  // d_f = direction_f * (normal_f x (v - u)) = eps_f * (normal_f x l), eps_f = direction_f *
  // lambda.
  const auto eps = [&](std::uint32_t f) { return faces[f].direction * lambda; };
  const auto signs = [&](std::uint32_t f, std::uint32_t g) {
    AngularSigns a = ExactAngularSigns(faces[f].normal, faces[g].normal, p, q);
    const int e = eps(f) * eps(g);
    // Counter-clockwise about v - u = lambda * l.
    return AngularSigns{a.orientation * e * lambda, a.dot * e};
  };
  const std::size_t m = faces.size();
  std::vector<int> half(m, 0);  // 1: (0, pi) from faces[0]; 2: pi; 3: (pi, 2 pi)
  for (std::uint32_t g = 1; g < m; ++g) {
    const AngularSigns a = signs(0, g);
    LINESURF_THROW_IF(a.orientation == 0 && a.dot > 0,
                      kInternal,
                      kVertexKeyGeometryStage,
                      "two faces leave an edge in the same direction");
    half[g] = a.orientation > 0 ? 1 : (a.orientation < 0 ? 3 : 2);
  }
  std::vector<std::uint32_t> order(m);
  for (std::uint32_t i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin() + 1, order.end(), [&](std::uint32_t f, std::uint32_t g) {
    if (half[f] != half[g]) return half[f] < half[g];
    return f != g && signs(f, g).orientation > 0;
  });
  for (std::size_t i = 1; i + 1 < m; ++i) {
    LINESURF_THROW_IF(
        half[order[i]] == half[order[i + 1]] && signs(order[i], order[i + 1]).orientation == 0,
        kInternal,
        kVertexKeyGeometryStage,
        "two faces leave an edge in the same direction");
  }
  return order;
}

}  // namespace linesurf::partition
