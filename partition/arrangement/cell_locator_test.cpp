#include "partition/arrangement/cell_locator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "partition/arrangement/build_cell_complex.h"
#include "partition/arrangement/cell_geometry.h"
#include "partition/arrangement/exact_predicates.h"

namespace linesurf::partition {
namespace {

CellComplex BuildRandom(std::uint64_t seed, std::size_t n, bool with_degenerate) {
  Rng rng(seed);
  Box3 box;
  box.min = Vec3(-1, -1, -1);
  box.max = Vec3(1, 1, 1);
  std::vector<Plane3> planes;
  if (with_degenerate) {
    planes.push_back(Plane3{Vec3::Zero(), Vec3(1, 0, 0)});
    planes.push_back(Plane3{Vec3::Zero(), Vec3(0, 1, 0)});
    planes.push_back(Plane3{Vec3::Zero(), Vec3(1, 1, 0)});
    planes.push_back(Plane3{Vec3::Zero(), Vec3(0, 0, 1)});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 normal = Vec3(rng.Normal(), rng.Normal(), rng.Normal()).normalized();
    planes.push_back(
        Plane3{Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)), normal});
  }
  auto r = BuildCellComplex(box, planes, {}, RunContext{});
  EXPECT_TRUE(r.has_value());
  return std::move(r).value().complex;
}

/// Brute force: the one cell whose every facet has the point on the cell's side.
CellId BruteForceLocate(const CellLocator& locator, const Vec3& p, std::span<const Vec3> dirs = {}) {
  const CellComplex& cx = locator.complex();
  CellId found;
  for (std::size_t i = 0; i < cx.NumCells(); ++i) {
    const CellId c(i);
    bool inside = true;
    for (const FacetId f : cx.cell_facets[c]) {
      const int cell_side = cx.facet_positive_cell[f] == c ? 1 : -1;
      if (locator.Side(p, cx.facet_plane[f], dirs) != cell_side) {
        inside = false;
        break;
      }
    }
    if (inside) {
      EXPECT_FALSE(found.IsValid()) << "two cells contain the point";
      found = c;
    }
  }
  return found;
}

/// Brute force for a point `mid` of segment ab rounded to doubles: for planes containing the
/// whole segment the rounded point may fall off the plane, so they take the endpoints' side.
CellId BruteForceLocateOnSegment(const CellLocator& locator, const Vec3& mid, const Vec3& a,
                                 const Vec3& b) {
  const CellComplex& cx = locator.complex();
  CellId found;
  for (std::size_t i = 0; i < cx.NumCells(); ++i) {
    const CellId c(i);
    bool inside = true;
    for (const FacetId f : cx.cell_facets[c]) {
      const ComplexPlaneId plane = cx.facet_plane[f];
      const Eigen::Vector4d& l = cx.planes[plane].coefficients;
      const bool contains_segment = ExactSignAtPoint(l, a) == 0 && ExactSignAtPoint(l, b) == 0;
      const int side = contains_segment ? locator.Side(a, plane) : locator.Side(mid, plane);
      if (side != (cx.facet_positive_cell[f] == c ? 1 : -1)) {
        inside = false;
        break;
      }
    }
    if (inside) found = c;
  }
  return found;
}

TEST(CellLocator, LocateAgreesWithBruteForce) {
  const CellComplex cx = BuildRandom(42, 12, true);
  const CellLocator locator(cx);
  Rng rng(43);
  for (int q = 0; q < 10000; ++q) {
    const Vec3 p(rng.Uniform(-1.2, 1.2), rng.Uniform(-1.2, 1.2), rng.Uniform(-1.2, 1.2));
    const CellId c = locator.Locate(p);
    ASSERT_EQ(c, BruteForceLocate(locator, p)) << "query " << q;
    if (c.IsValid()) {
      // The cell really contains the point (doubles, away from planes this is reliable).
      for (const FacetId f : cx.cell_facets[c]) {
        const Eigen::Vector4d& l = cx.planes[cx.facet_plane[f]].coefficients;
        const double value = l.head<3>().dot(p) + l[3];
        const double expected = cx.facet_positive_cell[f] == c ? 1.0 : -1.0;
        EXPECT_GE(value * expected, -1e-12);
      }
    } else {
      EXPECT_FALSE(cx.box.Contains(p));
    }
  }
}

TEST(CellLocator, TieRuleOnPlanesEdgesAndVertices) {
  const CellComplex cx = BuildRandom(7, 4, true);
  const CellLocator locator(cx);
  // The origin lies on 4 planes (x = 0, y = 0, x + y = 0, z = 0).
  const Vec3 origin = Vec3::Zero();
  std::vector<CellId> seen;
  for (const Vec3& d : {Vec3(1, 0.1, 0.2), Vec3(-1, 0.1, 0.2), Vec3(0.3, -1, -0.2), Vec3(-1, -1, -1)}) {
    const std::array<Vec3, 1> dirs{d};
    const CellId c = locator.Locate(origin, dirs);
    ASSERT_TRUE(c.IsValid());
    EXPECT_EQ(c, BruteForceLocate(locator, origin, dirs));
    // Same as a point slightly along d.
    EXPECT_EQ(c, locator.Locate(origin + 1e-6 * d));
    seen.push_back(c);
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end());
  // Without directions the fixed axes decide: the cell on the +x side of x = 0.
  const CellId c = locator.Locate(origin);
  EXPECT_EQ(c, BruteForceLocate(locator, origin));
  EXPECT_EQ(c, locator.Locate(Vec3(1e-9, 1e-10, 1e-11)));
  // Points on the box boundary with an outward direction are outside.
  const std::array<Vec3, 1> out{Vec3(1, 0, 0)};
  EXPECT_FALSE(locator.Locate(Vec3(1, 0.5, 0.5), out).IsValid());
  const std::array<Vec3, 1> in{Vec3(-1, 0, 0)};
  EXPECT_TRUE(locator.Locate(Vec3(1, 0.5, 0.5), in).IsValid());
}

void CheckWalk(const CellLocator& locator, const Vec3& a, const Vec3& b) {
  const CellComplex& cx = locator.complex();
  const CellId ca = locator.Locate(a), cb = locator.Locate(b);
  ASSERT_TRUE(ca.IsValid() && cb.IsValid());
  std::vector<std::pair<FacetId, double>> crossings;
  locator.WalkSegment(a, ca, b, cb, [&](FacetId f, double t) { crossings.emplace_back(f, t); });
  // The planes crossed are exactly those separating the endpoints, each once.
  std::vector<ComplexPlaneId> crossed, separating;
  for (const auto& [f, t] : crossings) crossed.push_back(cx.facet_plane[f]);
  for (std::size_t p = kNumBoxPlanes; p < cx.planes.size(); ++p) {
    if (locator.Side(a, ComplexPlaneId(p)) != locator.Side(b, ComplexPlaneId(p))) {
      separating.emplace_back(p);
    }
  }
  std::sort(crossed.begin(), crossed.end());
  ASSERT_EQ(crossed, separating);
  // Cell chain: each crossing leaves the current cell; midpoints lie in the cell between.
  CellId c = ca;
  double last_t = 0.0;
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const auto [f, t] = crossings[i];
    ASSERT_TRUE(cx.facet_positive_cell[f] == c || cx.facet_negative_cell[f] == c);
    ASSERT_GE(t, last_t);
    const double next_t = i + 1 < crossings.size() ? crossings[i + 1].second : 1.0;
    c = cx.Neighbour(f, c);
    if (next_t - t > 1e-9) {
      const Vec3 mid = a + 0.5 * (t + next_t) * (b - a);
      EXPECT_EQ(BruteForceLocateOnSegment(locator, mid, a, b), c);
    }
    last_t = t;
  }
  EXPECT_EQ(c, cb);
}

TEST(CellLocator, WalkSegmentAgreesWithBruteForce) {
  const CellComplex cx = BuildRandom(11, 10, false);
  const CellLocator locator(cx);
  Rng rng(12);
  for (int q = 0; q < 10000; ++q) {
    const Vec3 a(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    const Vec3 b(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    SCOPED_TRACE(q);
    CheckWalk(locator, a, b);
    if (HasFatalFailure()) return;
  }
}

TEST(CellLocator, LatticeQueriesOnPlanesEdgesAndVertices) {
  // Planes with few normals at quarter offsets; queries on the eighth grid lie on planes, edges
  // and vertices all the time.
  const std::array<Vec3, 6> normals{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                                    Vec3(1, 1, 0), Vec3(1, -1, 1), Vec3(0, 1, 1)};
  Rng rng(77);
  std::vector<Plane3> planes;
  auto lattice = [&](double step, int half) {
    return step * (static_cast<double>(rng.Below(2 * half + 1)) - half);
  };
  for (int k = 0; k < 24; ++k) {
    planes.push_back(Plane3{Vec3(lattice(0.25, 3), lattice(0.25, 3), lattice(0.25, 3)),
                            normals[rng.Below(normals.size())]});
  }
  Box3 box;
  box.min = Vec3(-1, -1, -1);
  box.max = Vec3(1, 1, 1);
  auto built = BuildCellComplex(box, planes, {}, RunContext{});
  ASSERT_TRUE(built.has_value());
  const CellLocator locator(built->complex);
  for (int q = 0; q < 2000; ++q) {
    const Vec3 a(lattice(0.125, 7), lattice(0.125, 7), lattice(0.125, 7));
    const Vec3 b(lattice(0.125, 7), lattice(0.125, 7), lattice(0.125, 7));
    const std::array<Vec3, 1> towards_b{b - a};
    const CellId c = locator.Locate(a, towards_b);
    ASSERT_EQ(c, BruteForceLocate(locator, a, towards_b));
    SCOPED_TRACE(q);
    CheckWalk(locator, a, b);
    if (HasFatalFailure()) return;
  }
}

TEST(CellLocator, WalkSegmentThroughEdgesAndVertices) {
  const CellComplex cx = BuildRandom(5, 6, true);
  const CellLocator locator(cx);
  // Segments through the origin (on 4 planes) and along the z axis (on 3 planes).
  CheckWalk(locator, Vec3(-0.5, -0.4, -0.3), Vec3(0.5, 0.4, 0.3));
  CheckWalk(locator, Vec3(-0.5, -0.5, -0.3), Vec3(0.5, 0.5, 0.3));
  CheckWalk(locator, Vec3(0.3, -0.3, -0.9), Vec3(-0.3, 0.3, 0.9));
  // A segment lying in the plane z = 0: endpoints located with a tie direction.
  const Vec3 a(-0.7, 0.2, 0), b(0.6, -0.1, 0);
  const std::array<Vec3, 1> up{Vec3(0, 0, 1)};
  const CellId ca = locator.Locate(a, up), cb = locator.Locate(b, up);
  std::size_t steps = 0;
  locator.WalkSegment(a, ca, b, cb, [&](FacetId, double) { ++steps; });
  EXPECT_LE(steps, cx.planes.size());
  // A target cell that does not contain `to`: the walk still ends there.
  const CellId elsewhere = locator.Locate(Vec3(0.9, 0.9, 0.9));
  ASSERT_NE(elsewhere, cb);
  CellId c = ca;
  locator.WalkSegment(a, ca, b, elsewhere, [&](FacetId f, double) { c = cx.Neighbour(f, c); });
  EXPECT_EQ(c, elsewhere);
}

}  // namespace
}  // namespace linesurf::partition
