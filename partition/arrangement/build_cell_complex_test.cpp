#include "partition/arrangement/build_cell_complex.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "partition/arrangement/cell_geometry.h"
#include "partition/arrangement/exact_predicates.h"
#include "partition/arrangement/validate_cell_complex.h"
#include "tests/support/thread_count.h"

namespace linesurf::partition {
namespace {

/// Relative error allowed on the sum of cell volumes against the box volume.
constexpr double kVolumeRelativeTolerance = 1e-9;

Box3 MakeBox(const Vec3& lo, const Vec3& hi) {
  Box3 box;
  box.min = lo;
  box.max = hi;
  return box;
}

CellComplexResult Build(const Box3& box, const std::vector<Plane3>& planes) {
  auto result = BuildCellComplex(box, planes, {}, RunContext{});
  EXPECT_TRUE(result.has_value()) << (result ? "" : result.error().ToString());
  return std::move(result).value();
}

void ExpectValidWithVolume(const CellComplex& cx) {
  const Status ok = ValidateCellComplex(cx);
  ASSERT_TRUE(ok.has_value()) << ok.error().ToString();
  double sum = 0.0;
  for (std::size_t c = 0; c < cx.NumCells(); ++c) {
    const double v = CellVolume(cx, CellId(c));
    EXPECT_GT(v, 0.0) << "cell " << c;
    sum += v;
  }
  const Vec3 e = cx.box.Extent();
  const double box_volume = e.x() * e.y() * e.z();
  EXPECT_LT(std::abs(sum - box_volume), kVolumeRelativeTolerance * box_volume);
}

Vec3 RandomUnit(Rng& rng) {
  Vec3 n(rng.Normal(), rng.Normal(), rng.Normal());
  return n.normalized();
}

TEST(ExactPredicates, SignAtPointIsExactWhereDoublesRoundTheWrongWay) {
  // 1e16 + 3 - 1e16 - 3.5 = -0.5, but in doubles 1e16 + 3 rounds to 1e16 + 4 and the sum to +0.5:
  // the double filter must not decide it.
  EXPECT_EQ(ExactSignAtPoint(Eigen::Vector4d(1, 1, -1, -3.5), Vec3(1e16, 3, 1e16)), -1);
  EXPECT_EQ(ExactSignAtPoint(Eigen::Vector4d(1, 1, -1, -3), Vec3(1e16, 3, 1e16)), 0);
  EXPECT_EQ(ExactSignAtPoint(Eigen::Vector4d(1, 1, -1, -2.5), Vec3(1e16, 3, 1e16)), 1);
  // One ulp off a plane far from the origin, and clearly off it.
  const double x0 = 1e6 + 0.1;
  const Eigen::Vector4d plane(1, 0, 0, -x0);
  EXPECT_EQ(ExactSignAtPoint(plane, Vec3(x0, 1e6, -1e6)), 0);
  EXPECT_EQ(ExactSignAtPoint(plane, Vec3(std::nextafter(x0, 2e6), 1e6, -1e6)), 1);
  EXPECT_EQ(ExactSignAtPoint(plane, Vec3(std::nextafter(x0, 0.0), 1e6, -1e6)), -1);
  EXPECT_EQ(ExactSignAtPoint(plane, Vec3(x0 + 1, 1e6, -1e6)), 1);
  EXPECT_EQ(ExactSignDot(Vec3(1, 1, -1), Vec3(1e16, 2, 1e16)), 1);
  EXPECT_EQ(ExactSignDot(Vec3(1, 1, -1), Vec3(1e16, 0, 1e16)), 0);
}

TEST(ExactPredicates, VertexSignConvention) {
  const Eigen::Vector4d x(1, 0, 0, 0), y(0, 1, 0, 0), z(0, 0, 1, 0);
  const Eigen::Vector4d x_minus_one(1, 0, 0, -1);  // negative at the origin
  EXPECT_EQ(ExactSignAtVertex(x, y, z, x_minus_one), -1);
  EXPECT_EQ(ExactSignAtVertex(y, x, z, x_minus_one), -1);   // odd permutation
  EXPECT_EQ(ExactSignAtVertex(-x, y, z, x_minus_one), -1);  // flipped plane
  EXPECT_EQ(ExactSignAtVertex(x, y, z, -x_minus_one), 1);
  EXPECT_EQ(ExactSignAtVertex(x, y, z, Eigen::Vector4d(1, 1, 1, 0)), 0);
  // The vertex (1, 2, 3) of shifted planes against x + y + z - 6.5.
  const Eigen::Vector4d a(1, 0, 0, -1), b(0, 2, 0, -4), c(1, 1, 1, -6);
  EXPECT_EQ(ExactSignAtVertex(a, b, c, Eigen::Vector4d(1, 1, 1, -6.5)), -1);
  EXPECT_EQ(ExactSignAtVertex(c, a, b, Eigen::Vector4d(1, 1, 1, -5.5)), 1);
  // Nearly coincident planes are told apart exactly.
  EXPECT_EQ(ExactSignAtPoint(Eigen::Vector4d(1, 0, 0, -0.3), Vec3(0.3 + 1e-17, 0, 0)), 0);
  EXPECT_EQ(ExactSignAtPoint(Eigen::Vector4d(1, 0, 0, -0.3), Vec3(std::nextafter(0.3, 1.0), 0, 0)), 1);
  EXPECT_EQ(ExactProportionality(Eigen::Vector4d(1, 2, 3, 4), Eigen::Vector4d(-2, -4, -6, -8)), -1);
  EXPECT_EQ(ExactProportionality(Eigen::Vector4d(1, 2, 3, 4), Eigen::Vector4d(0.5, 1, 1.5, 2)), 1);
  EXPECT_EQ(ExactProportionality(Eigen::Vector4d(1, 2, 3, 4), Eigen::Vector4d(1, 2, 3, 4 + 1e-12)), 0);
}

TEST(BuildCellComplex, EmptyPlaneSetGivesTheBox) {
  const auto r = Build(MakeBox(Vec3(-1, -2, -3), Vec3(1, 2, 3)), {});
  EXPECT_EQ(r.complex.NumCells(), 1u);
  EXPECT_EQ(r.complex.NumFacets(), 6u);
  EXPECT_EQ(r.complex.NumEdges(), 12u);
  EXPECT_EQ(r.complex.NumVertices(), 8u);
  ExpectValidWithVolume(r.complex);
}

TEST(BuildCellComplex, AxisAlignedGridCounts) {
  for (const auto& [a, b, c] : {std::array<int, 3>{1, 0, 0}, std::array<int, 3>{2, 3, 4},
                                std::array<int, 3>{5, 1, 2}, std::array<int, 3>{4, 4, 4}}) {
    std::vector<Plane3> planes;
    const std::array<int, 3> count{a, b, c};
    for (int axis = 0; axis < 3; ++axis) {
      for (int k = 1; k <= count[axis]; ++k) {
        Vec3 point = Vec3::Zero();
        point[axis] = -1.0 + 2.0 * k / (count[axis] + 1) + 0.01;
        planes.push_back(Plane3{point, Vec3::Unit(axis) * (k % 2 == 0 ? 1.0 : -1.0)});
      }
    }
    const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)), planes);
    const std::size_t A = a, B = b, C = c;
    SCOPED_TRACE(::testing::Message() << a << "," << b << "," << c);
    EXPECT_EQ(r.stats.planes_used, A + B + C);
    EXPECT_EQ(r.complex.NumCells(), (A + 1) * (B + 1) * (C + 1));
    EXPECT_EQ(r.complex.NumVertices(), (A + 2) * (B + 2) * (C + 2));
    EXPECT_EQ(r.complex.NumEdges(),
              (A + 1) * (B + 2) * (C + 2) + (A + 2) * (B + 1) * (C + 2) + (A + 2) * (B + 2) * (C + 1));
    EXPECT_EQ(r.complex.NumFacets(),
              (A + 2) * (B + 1) * (C + 1) + (A + 1) * (B + 2) * (C + 1) + (A + 1) * (B + 1) * (C + 2));
    ExpectValidWithVolume(r.complex);
  }
}

/// True when the line of planes p and q meets the open box (slab clipping, doubles: fine in
/// general position).
bool LineMeetsBox(const Plane3& p, const Plane3& q, const Box3& box) {
  const Vec3 dir = p.normal.cross(q.normal);
  // A point on both planes: least-norm solution of [np; nq] x = [np.pp; nq.pq].
  Eigen::Matrix<double, 2, 3> m;
  m.row(0) = p.normal.transpose();
  m.row(1) = q.normal.transpose();
  const Eigen::Vector2d rhs(p.normal.dot(p.point), q.normal.dot(q.point));
  const Vec3 x0 = m.transpose() * (m * m.transpose()).inverse() * rhs;
  double t0 = -1e300, t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-300) {
      if (x0[a] <= box.min[a] || x0[a] >= box.max[a]) return false;
      continue;
    }
    double u = (box.min[a] - x0[a]) / dir[a], v = (box.max[a] - x0[a]) / dir[a];
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
  }
  return t0 < t1;
}

TEST(BuildCellComplex, RandomPlanesInGeneralPosition) {
  const Box3 box = MakeBox(Vec3(-1, -1.5, -0.5), Vec3(1.2, 1, 0.7));
  for (std::uint64_t trial = 0; trial < 4; ++trial) {
    Rng rng(1000 * 7 + trial);
    const std::size_t n = 6 + 4 * trial;
    std::vector<Plane3> planes;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 point(rng.Uniform(box.min.x(), box.max.x()), rng.Uniform(box.min.y(), box.max.y()),
                       rng.Uniform(box.min.z(), box.max.z()));
      planes.push_back(Plane3{point, RandomUnit(rng)});
    }
    std::size_t lines = 0, points = 0;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        lines += LineMeetsBox(planes[i], planes[j], box) ? 1 : 0;
        for (std::size_t k = j + 1; k < n; ++k) {
          Eigen::Matrix3d m;
          m.row(0) = planes[i].normal;
          m.row(1) = planes[j].normal;
          m.row(2) = planes[k].normal;
          const Vec3 rhs(planes[i].normal.dot(planes[i].point), planes[j].normal.dot(planes[j].point),
                         planes[k].normal.dot(planes[k].point));
          const Vec3 x = m.partialPivLu().solve(rhs);
          points += (x.array() > box.min.array()).all() && (x.array() < box.max.array()).all();
        }
      }
    }
    const auto r = Build(box, planes);
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    EXPECT_EQ(r.stats.planes_used, n);
    EXPECT_EQ(r.complex.NumCells(), 1 + n + lines + points);
    ExpectValidWithVolume(r.complex);
  }
}

TEST(BuildCellComplex, TenPlanesThroughOneLine) {
  std::vector<Plane3> planes;
  for (int k = 0; k < 10; ++k) {
    const double angle = std::numbers::pi * k / 10.0 + 0.05;
    planes.push_back(Plane3{Vec3::Zero(), Vec3(std::cos(angle), std::sin(angle), 0.0)});
  }
  const auto r = Build(MakeBox(Vec3(-1, -0.7, -1), Vec3(1.3, 1, 0.5)), planes);
  EXPECT_EQ(r.complex.NumCells(), 20u);
  ExpectValidWithVolume(r.complex);
  // Every vertex on the common line keeps the lexicographically smallest independent triple.
  for (std::size_t v = 0; v < r.complex.NumVertices(); ++v) {
    const auto& t = r.complex.vertex_planes[VertexId(v)];
    const Vec3& p = r.complex.vertex_points[VertexId(v)];
    if (p.head<2>().norm() < 1e-12 && t[0].index() >= kNumBoxPlanes) ADD_FAILURE() << "vertex " << v;
  }
}

TEST(BuildCellComplex, SixPlanesThroughOnePoint) {
  Rng rng(1000 * 3 + 0);
  std::vector<Plane3> planes;
  for (int k = 0; k < 6; ++k) planes.push_back(Plane3{Vec3::Zero(), RandomUnit(rng)});
  const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1.5, 1)), planes);
  EXPECT_EQ(r.complex.NumCells(), 6u * 5u + 2u);  // central arrangement in general position
  ExpectValidWithVolume(r.complex);
}

TEST(BuildCellComplex, DuplicateOppositeTouchingAndOutsidePlanesAreSkipped) {
  std::vector<Plane3> planes{
      Plane3{Vec3(0.25, 0, 0), Vec3(1, 0, 0)},
      Plane3{Vec3(0.25, 0.5, 0.5), Vec3(1, 0, 0)},  // duplicate
      Plane3{Vec3(0.25, 0, 0), Vec3(-1, 0, 0)},     // opposite
      Plane3{Vec3(-1, -1, -1), Vec3(1, 1, 1)},      // touches the corner only
      Plane3{Vec3(1, 0, 0), Vec3(1, 0, 0)},         // on a box face
      Plane3{Vec3(3, 0, 0), Vec3(1, 0, 0)},         // misses the box
      Plane3{Vec3(0, 0, 0), Vec3(0, 0, 0)},         // invalid
      Plane3{Vec3(0, 0.1, 0), Vec3(0, 1, 0)},
  };
  const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)), planes);
  EXPECT_EQ(r.stats.planes_used, 2u);
  EXPECT_EQ(r.stats.planes_duplicate, 2u);
  EXPECT_EQ(r.stats.planes_skipped_touching, 2u);
  EXPECT_EQ(r.stats.planes_skipped_outside, 1u);
  EXPECT_EQ(r.stats.planes_invalid, 1u);
  EXPECT_EQ(r.complex.NumCells(), 4u);
  EXPECT_EQ(r.complex.planes[ComplexPlaneId(std::size_t{6})].source, PlaneId(std::size_t{0}));
  EXPECT_EQ(r.complex.planes[ComplexPlaneId(std::size_t{7})].source, PlaneId(std::size_t{7}));
  EXPECT_FALSE(r.warnings.empty());
  ExpectValidWithVolume(r.complex);
}

TEST(BuildCellComplex, NearlyCoincidentAndDegenerateMix) {
  Rng rng(1000 * 11 + 0);
  std::vector<Plane3> planes{
      Plane3{Vec3(0.3, 0, 0), Vec3(1, 0, 0)},
      Plane3{Vec3(0.3 + 1e-9, 0, 0), Vec3(1, 0, 0)},
      Plane3{Vec3(0.3, 0, 0), Vec3(1, 1e-9, 0).normalized()},
      Plane3{Vec3(-1, -1, -1), Vec3(1, -1, 0.5)},  // through a corner, crossing the box
      Plane3{Vec3::Zero(), Vec3(1, 0, 0)},
      Plane3{Vec3::Zero(), Vec3(0, 1, 0)},
      Plane3{Vec3::Zero(), Vec3(0, 0, 1)},
      Plane3{Vec3::Zero(), Vec3(1, 1, 0)},
      Plane3{Vec3::Zero(), Vec3(1, -1, 0)},
      Plane3{Vec3::Zero(), Vec3(1, 1, 1)},
  };
  for (int k = 0; k < 8; ++k) {
    planes.push_back(
        Plane3{Vec3(rng.Uniform(-0.5, 0.5), rng.Uniform(-0.5, 0.5), 0), RandomUnit(rng)});
  }
  const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)), planes);
  EXPECT_EQ(r.stats.planes_used, planes.size());
  ExpectValidWithVolume(r.complex);
}

TEST(BuildCellComplex, LatticeOfCoincidentPlanes) {
  // Few normals and quarter offsets: many duplicates, many planes through shared lines and
  // points, planes through box edges and corners.
  const std::array<Vec3, 12> normals{Vec3(1, 0, 0), Vec3(0, 1, 0),  Vec3(0, 0, 1),  Vec3(1, 1, 0),
                                     Vec3(1, -1, 0), Vec3(1, 0, 1), Vec3(0, 1, -1), Vec3(1, 1, 1),
                                     Vec3(1, -1, 1), Vec3(-1, 1, 1), Vec3(2, 1, 0), Vec3(1, 2, 3)};
  for (std::uint64_t trial = 0; trial < 3; ++trial) {
    Rng rng(9000 + trial);
    std::vector<Plane3> planes;
    for (int k = 0; k < 40; ++k) {
      const Vec3 point(0.25 * (static_cast<double>(rng.Below(7)) - 3.0),
                       0.25 * (static_cast<double>(rng.Below(7)) - 3.0),
                       0.25 * (static_cast<double>(rng.Below(7)) - 3.0));
      planes.push_back(Plane3{point, normals[rng.Below(normals.size())]});
    }
    const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)), planes);
    SCOPED_TRACE(trial);
    EXPECT_GT(r.stats.planes_duplicate, 0u);
    ExpectValidWithVolume(r.complex);
  }
}

void ExpectSameComplex(const CellComplex& a, const CellComplex& b) {
  ASSERT_EQ(a.NumCells(), b.NumCells());
  EXPECT_EQ(a.vertex_planes.raw(), b.vertex_planes.raw());
  EXPECT_EQ(a.edge_vertices.raw(), b.edge_vertices.raw());
  EXPECT_EQ(a.facet_vertices.items(), b.facet_vertices.items());
  EXPECT_EQ(a.facet_vertices.offsets(), b.facet_vertices.offsets());
  EXPECT_EQ(a.edge_facets.items(), b.edge_facets.items());
  EXPECT_EQ(a.edge_cells.items(), b.edge_cells.items());
  EXPECT_EQ(a.cell_facets.items(), b.cell_facets.items());
  EXPECT_EQ(a.facet_positive_cell.raw(), b.facet_positive_cell.raw());
  EXPECT_EQ(a.facet_negative_cell.raw(), b.facet_negative_cell.raw());
  EXPECT_EQ(a.cell_colour.raw(), b.cell_colour.raw());
  for (std::size_t v = 0; v < a.NumVertices(); ++v) {
    EXPECT_EQ(a.vertex_points[VertexId(v)], b.vertex_points[VertexId(v)]);
  }
}

TEST(BuildCellComplexes, IdenticalForAnyThreadCount) {
  Rng rng(1000 * 5 + 0);
  std::vector<Plane3> planes;
  for (int k = 0; k < 14; ++k) {
    planes.push_back(
        Plane3{Vec3(rng.Uniform(-2, 2), rng.Uniform(-2, 2), rng.Uniform(-1, 1)), RandomUnit(rng)});
  }
  std::vector<Box3> boxes;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 2; ++j) {
      boxes.push_back(MakeBox(Vec3(-2 + i, -2 + 2 * j, -1), Vec3(-1 + i, 2 * j, 1)));
    }
  }
  std::vector<std::vector<CellComplexResult>> runs;
  const linesurf::testing::RealThreadCounts real_threads;
  for (const int threads : {1, 2, 3, 8}) {
    RunContext ctx;
    ctx.num_threads = threads;
    auto r = BuildCellComplexes(boxes, planes, {}, ctx);
    ASSERT_TRUE(r.has_value()) << r.error().ToString();
    ASSERT_EQ(r->size(), boxes.size());
    runs.push_back(std::move(r).value());
  }
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    EXPECT_TRUE(ValidateCellComplex(runs[0][b].complex).has_value());
    const auto single = Build(boxes[b], planes);
    ExpectSameComplex(runs[0][b].complex, single.complex);
    for (std::size_t t = 1; t < runs.size(); ++t) ExpectSameComplex(runs[0][b].complex, runs[t][b].complex);
  }
}

TEST(BuildCellComplex, CancelAndCellLimit) {
  std::vector<Plane3> planes;
  for (int k = 0; k < 6; ++k) planes.push_back(Plane3{Vec3(0.1 * k - 0.25, 0, 0), Vec3(1, 0, 0)});
  const Box3 box = MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  RunContext cancelled;
  cancelled.is_cancelled = [] { return true; };
  auto r = BuildCellComplex(box, planes, {}, cancelled);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kCancelled);
  CellComplexOptions options;
  options.max_cells = 4;
  r = BuildCellComplex(box, planes, options, RunContext{});
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kResourceExhausted);
  options.max_cells = 7;
  EXPECT_TRUE(BuildCellComplex(box, planes, options, RunContext{}).has_value());
}

TEST(BuildCellComplex, FarPlaneReferencePointsInLocalFrame) {
  // Planes given by points 2,000 units away (as in real inputs) still split the local box.
  std::vector<Plane3> planes{
      Plane3{Vec3(2000, 0.2, 0), Vec3(0, 1, 0)},
      Plane3{Vec3(0.3, -2000, 0), Vec3(1, 0, 0)},
      Plane3{Vec3(0, 0, 0.1) + 2000 * Vec3(1, -1, 0).normalized(), Vec3(0.1, 0.1, 1).normalized()}};
  const auto r = Build(MakeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)), planes);
  EXPECT_EQ(r.stats.planes_used, 3u);
  EXPECT_EQ(r.complex.NumCells(), 8u);
  ExpectValidWithVolume(r.complex);
}

TEST(BuildCellComplex, RejectsBadBoxAndOptions) {
  EXPECT_FALSE(BuildCellComplex(Box3{}, {}, {}, RunContext{}).has_value());
  CellComplexOptions options;
  options.max_centre_offset_in_diagonals = 0;
  EXPECT_EQ(BuildCellComplex(MakeBox(Vec3::Zero(), Vec3::Ones()), {}, options, RunContext{}).error().code,
            ErrorCode::kInvalidOptions);
}

}  // namespace
}  // namespace linesurf::partition
