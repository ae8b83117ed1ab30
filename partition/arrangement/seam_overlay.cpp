#include "partition/arrangement/seam_overlay.h"

#include "engine/core/exception.h"
#include "partition/arrangement/exact_predicates.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace linesurf::partition {
namespace {

constexpr char kSeamOverlayStage[] = "seam_overlay";
/// Padding of the rounded polygon boxes, relative to the face's size, before exact clipping:
/// far above the error of rounded vertices (their certified boxes are at most 1e-10 relative
/// wide, exact_predicates.cpp).
constexpr double kBoxPadding = 1e-9;
/// Same margin for the double separation test, relative to the magnitude of the evaluation.
constexpr double kSeparationMargin = 1e-8;

/// true when some edge line of `b` has every rounded vertex of `a` outside it by more than the
/// rounding error could explain: the polygons are then certainly disjoint (a double filter that
/// spares the exact clipping of most pairs whose boxes overlap).
bool Separated(const BlockComplexes& cx, const SeamPolygon& a, const SeamPolygon& b) {
  for (std::size_t e = 0; e < b.edge_planes.size(); ++e) {
    const Eigen::Vector4d c = b.edge_sides[e] * cx.Coefficients(b.edge_planes[e]);
    bool all_outside = true;
    for (const Vec3& p : a.points) {
      const double value = c.head<3>().dot(p) + c[3];
      const double magnitude = c.head<3>().cwiseAbs().dot(p.cwiseAbs()) + std::abs(c[3]);
      if (!(value < -kSeparationMargin * magnitude)) {
        all_outside = false;
        break;
      }
    }
    if (all_outside) return true;
  }
  return false;
}

VertexKey Sorted(PlaneKey a, PlaneKey b, PlaneKey c) {
  VertexKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

Vec3 RoundedPoint(const BlockComplexes& cx, const VertexKey& v) {
  return ComputeVertexBounds(cx.Coefficients(v[0]), cx.Coefficients(v[1]), cx.Coefficients(v[2]))
      .approx;
}

/// A polygon while it is clipped: vertex i with the plane of its outgoing edge.
struct Ring {
  std::vector<VertexKey> vertices;
  std::vector<PlaneKey> edges;
};

/// Sutherland-Hodgman against side * sign(q) >= 0, exactly. A crossing vertex is the triple
/// (face, edge plane, q).
Ring Clip(const BlockComplexes& cx, PlaneKey face, const Ring& in, PlaneKey q, int side) {
  const std::size_t n = in.vertices.size();
  std::vector<int> s(n);
  bool any_inside = false;
  bool any_outside = false;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side * SignAt(cx, in.vertices[i], q);
    any_inside |= s[i] > 0;
    any_outside |= s[i] < 0;
  }
  if (!any_outside) return in;
  Ring out;
  if (!any_inside) return out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const PlaneKey e = in.edges[i];
    if (s[i] >= 0) {
      out.vertices.push_back(in.vertices[i]);
      out.edges.push_back(s[j] >= 0 || s[i] > 0 ? e : q);
      if (s[i] > 0 && s[j] < 0) {
        out.vertices.push_back(Sorted(face, e, q));
        out.edges.push_back(q);
      }
    } else if (s[j] > 0) {
      out.vertices.push_back(Sorted(face, e, q));
      out.edges.push_back(e);
    }
  }
  if (out.vertices.size() < 3 || !HasArea(cx, out.vertices, out.edges)) {
    out.vertices.clear();
    out.edges.clear();
  }
  return out;
}

}  // namespace

PlaneKey BoxPlaneKey(const Eigen::Vector3i& base, int local) {
  const int axis = local % 3;
  return PlaneKey::Face(axis, base[axis] + (local >= 3 ? 1 : 0));
}

int SignAt(const BlockComplexes& cx, const VertexKey& v, PlaneKey plane) {
  for (const PlaneKey k : v) {
    if (k == plane) return 0;
  }
  return ExactSignAtVertex(
      cx.Coefficients(v[0]), cx.Coefficients(v[1]), cx.Coefficients(v[2]), cx.Coefficients(plane));
}

std::vector<SeamPolygon> FacePolygons(const BlockComplex& block, int local_face) {
  const CellComplex& c = block.complex;
  std::vector<SeamPolygon> out;
  for (std::size_t fi = 0; fi < c.NumFacets(); ++fi) {
    const FacetId f(fi);
    if (c.facet_plane[f].index() != static_cast<std::size_t>(local_face)) continue;
    SeamPolygon poly;
    poly.facet = f;
    poly.cell = c.facet_positive_cell[f];  // box planes point into the block
    poly.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    poly.hi = -poly.lo;
    const auto vertices = c.facet_vertices[f];
    const auto edges = c.facet_edges[f];
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const auto& t = c.vertex_planes[vertices[i]];
      poly.vertices.push_back(Sorted(block.plane_keys[t[0].index()],
                                     block.plane_keys[t[1].index()],
                                     block.plane_keys[t[2].index()]));
      poly.points.push_back(c.vertex_points[vertices[i]]);
      poly.lo = poly.lo.cwiseMin(c.vertex_points[vertices[i]]);
      poly.hi = poly.hi.cwiseMax(c.vertex_points[vertices[i]]);
      // The other facet of the cell on this edge carries the edge's line.
      FacetId other;
      for (const FacetId g : c.edge_facets[edges[i]]) {
        if (g != f &&
            (c.facet_positive_cell[g] == poly.cell || c.facet_negative_cell[g] == poly.cell)) {
          other = g;
          break;
        }
      }
      LINESURF_THROW_IF(
          !other.IsValid(), kInternal, kSeamOverlayStage, "facet edge without a second facet");
      const std::size_t local = c.facet_plane[other].index();
      const bool positive = c.facet_positive_cell[other] == poly.cell;
      // Box planes point into the block; the global key of a max face points the other way.
      const int orientation = local >= 3 && local < kNumBoxPlanes ? -1 : 1;
      poly.edge_planes.push_back(block.plane_keys[local]);
      poly.edge_sides.push_back((positive ? 1 : -1) * orientation);
    }
    out.push_back(std::move(poly));
  }
  return out;
}

std::vector<SeamFacet> OverlayFace(const BlockComplexes& cx,
                                   PlaneKey face,
                                   const std::vector<SeamPolygon>& lower,
                                   const std::vector<SeamPolygon>& upper) {
  std::vector<SeamFacet> out;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const SeamPolygon& p : lower) {
    lo = lo.cwiseMin(p.lo);
    hi = hi.cwiseMax(p.hi);
  }
  const double pad = kBoxPadding * (hi - lo).norm();
  for (const SeamPolygon& a : lower) {
    for (const SeamPolygon& b : upper) {
      if (((a.lo.array() - pad) > b.hi.array()).any() ||
          ((b.lo.array() - pad) > a.hi.array()).any()) {
        continue;
      }
      if (Separated(cx, a, b) || Separated(cx, b, a)) continue;
      Ring ring{a.vertices, a.edge_planes};
      for (std::size_t e = 0; e < b.edge_planes.size() && !ring.vertices.empty(); ++e) {
        ring = Clip(cx, face, ring, b.edge_planes[e], b.edge_sides[e]);
      }
      if (ring.vertices.empty()) continue;
      SeamFacet facet;
      facet.lower_facet = a.facet;
      facet.upper_facet = b.facet;
      facet.lower_cell = a.cell;
      facet.upper_cell = b.cell;
      facet.vertices = std::move(ring.vertices);
      facet.edge_planes = std::move(ring.edges);
      for (const VertexKey& v : facet.vertices) facet.points.push_back(RoundedPoint(cx, v));
      out.push_back(std::move(facet));
    }
  }
  return out;
}

bool HasArea(const BlockComplexes& cx,
             const std::vector<VertexKey>& vertices,
             const std::vector<PlaneKey>& edge_planes) {
  for (const PlaneKey e : edge_planes) {
    for (const VertexKey& v : vertices) {
      if (SignAt(cx, v, e) != 0) return true;
    }
  }
  return false;
}

double PolygonArea(const std::vector<Vec3>& points) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    sum += (points[i] - points[0]).cross(points[i + 1] - points[0]);
  }
  return 0.5 * sum.norm();
}

}  // namespace linesurf::partition
