#include "engine/pipeline/surface_quality.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace linesurf::pipeline {
namespace {

constexpr double kEps = 0.01;

/// Appends the box [lo, hi] with faces counter-clockwise seen from outside.
void AddBox(PolygonMesh& mesh, const Vec3& lo, const Vec3& hi) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back(
        i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  }
  constexpr std::array<std::array<std::uint32_t, 4>, 6> kFaces{
      {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
  for (const auto& f : kFaces) {
    const std::array<std::uint32_t, 4> face{base + f[0], base + f[1], base + f[2], base + f[3]};
    mesh.AddFace(face);
  }
}

/// The cube [-1, 1]^3: its 6 planes (order -x, +x, -y, +y, -z, +z), a textural segment across
/// the middle of every face seen from 5 units along the face normal, and its 12 edges, each seen
/// from outside both of its faces.
Scene CubeScene() {
  Scene scene;
  const std::array<Vec3, 6> normals{
      -Vec3::UnitX(), Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitY(), -Vec3::UnitZ(), Vec3::UnitZ()};
  for (const Vec3& n : normals) scene.planes.push_back(Plane3{n, n});
  const auto add = [&](const Segment3& s, const Vec3& eye, PlaneMembership m) {
    scene.segments.push_back(s);
    scene.viewpoints.push_back(eye);
    const std::array<ViewpointId, 1> row{ViewpointId(scene.viewpoints.size() - 1)};
    scene.observations.AddRow(row);
    scene.memberships.push_back(m);
  };
  for (std::uint32_t p = 0; p < 6; ++p) {
    const Vec3 n = normals[p];
    const Vec3 along = n.cross(std::abs(n.z()) > 0.5 ? Vec3::UnitX() : Vec3::UnitZ());
    PlaneMembership m;
    m.Add(PlaneId(p));
    add(Segment3{n - 0.8 * along, n + 0.8 * along}, 5.0 * n, m);
  }
  for (std::uint32_t a = 0; a < 6; ++a) {
    for (std::uint32_t b = a + 1; b < 6; ++b) {
      const Vec3 na = normals[a], nb = normals[b];
      if (std::abs(na.dot(nb)) > 0.5) continue;  // opposite faces share no edge
      const Vec3 dir = na.cross(nb);
      PlaneMembership m;
      m.Add(PlaneId(a));
      m.Add(PlaneId(b));
      add(Segment3{na + nb - dir, na + nb + dir}, 3.0 * (na + nb), m);
    }
  }
  return scene;
}

SurfaceQuality Measure(const PolygonMesh& mesh, const Scene& scene, int threads = 0) {
  RunContext ctx;
  ctx.num_threads = threads;
  Expected<SurfaceQuality> q = MeasureSurfaceQuality(mesh, scene, kEps, {}, ctx);
  EXPECT_TRUE(q.has_value()) << (q ? "" : q.error().message);
  return q ? *q : SurfaceQuality{};
}

TEST(SurfaceQuality, PerfectReconstructionScoresFull) {
  const Scene scene = CubeScene();
  ASSERT_EQ(scene.NumSegments(), 18u);
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const SurfaceQuality q = Measure(mesh, scene);
  EXPECT_EQ(q.supported_segments, 18u);
  EXPECT_NEAR(q.data_fit, 1.0, 1e-12);
  EXPECT_NEAR(q.visibility_consistency, 1.0, 1e-12);
  ASSERT_EQ(q.components.size(), 1u);
  EXPECT_NEAR(q.components[0].volume, 8.0, 1e-12);
  EXPECT_EQ(q.components[0].supported_segments, 18u);
  EXPECT_EQ(q.floating_fragments, 0u);
  EXPECT_NEAR(q.largest_component_share, 1.0, 1e-12);
  EXPECT_TRUE(q.planes_off_surface.empty());
}

TEST(SurfaceQuality, PlanesOffSurfaceAreThoseNoFaceLiesOn) {
  Scene scene = CubeScene();
  // Within eps of the +x face: on it. Through the cube, crossing four faces: off. Half an eps
  // past the slab of the -z face, tilted: off.
  scene.planes.push_back(Plane3{Vec3(1.0 + 0.5 * kEps, 0, 0), Vec3::UnitX()});
  scene.planes.push_back(Plane3{Vec3(0.5, 0, 0), Vec3::UnitX()});
  scene.planes.push_back(Plane3{Vec3(0, 0, -1.0 - 1.5 * kEps), Vec3(0.001, 0, 1).normalized()});
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_EQ(Measure(mesh, scene).planes_off_surface, (std::vector<std::uint32_t>{7, 8}));
}

TEST(SurfaceQuality, ShrunkBoxLosesDataFit) {
  // Every face 5 cm inside: farther than 2 eps from every segment.
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-0.95, -0.95, -0.95), Vec3(0.95, 0.95, 0.95));
  const SurfaceQuality q = Measure(mesh, CubeScene());
  EXPECT_LT(q.data_fit, 1e-12);
  EXPECT_EQ(q.floating_fragments, 1u);  // nothing supported lies on it
  EXPECT_EQ(q.planes_off_surface.size(), 6u);
}

TEST(SurfaceQuality, FloatingBoxIsOneFragment) {
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(10, 10, 10), Vec3(10.5, 10.5, 10.5));
  const SurfaceQuality q = Measure(mesh, CubeScene());
  ASSERT_EQ(q.components.size(), 2u);
  EXPECT_EQ(q.floating_fragments, 1u);
  EXPECT_FALSE(q.components[0].floating);
  EXPECT_TRUE(q.components[1].floating);
  EXPECT_NEAR(q.components[1].volume, 0.125, 1e-12);
  EXPECT_NEAR(q.largest_component_share, 8.0 / 8.125, 1e-12);
  EXPECT_NEAR(q.data_fit, 1.0, 1e-12);
}

TEST(SurfaceQuality, ABoxHoldingFewerThanThreeLinesIsAFragment) {
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(10, 10, 10), Vec3(11, 11, 11));
  Scene scene = CubeScene();
  const auto add_on_far_top = [&](double y, double x0, double x1) {
    scene.segments.push_back(Segment3{Vec3(x0, y, 11), Vec3(x1, y, 11)});
    scene.viewpoints.push_back(Vec3(10.5, 10.5, 15));
    const std::array<ViewpointId, 1> row{ViewpointId(scene.viewpoints.size() - 1)};
    scene.observations.AddRow(row);
    PlaneMembership m;
    m.Add(PlaneId(5u));
    scene.memberships.push_back(m);
  };
  add_on_far_top(10.3, 10.1, 10.5);  // line 1, in two parts (a residual split)
  add_on_far_top(10.3, 10.5, 10.9);
  add_on_far_top(10.6, 10.1, 10.9);  // line 2
  SurfaceQuality q = Measure(mesh, scene);
  ASSERT_EQ(q.components.size(), 2u);
  EXPECT_EQ(q.components[1].supported_segments, 3u);
  EXPECT_EQ(q.components[1].supported_lines, 2u);
  EXPECT_EQ(q.floating_fragments, 1u);
  add_on_far_top(10.9, 10.1, 10.9);  // line 3
  q = Measure(mesh, scene);
  EXPECT_EQ(q.components[1].supported_lines, 3u);
  EXPECT_EQ(q.floating_fragments, 0u);
}

TEST(SurfaceQuality, OccludingWallLowersVisibilityConsistency) {
  // A plate between the +x face and its viewpoint (5, 0, 0) blocks the view of that face's
  // segment (one of 18 supported segments, length 1.6 of 1.6 x 6 + 2 x 12).
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(2.0, -1.5, -1.5), Vec3(2.2, 1.5, 1.5));
  const SurfaceQuality q = Measure(mesh, CubeScene());
  EXPECT_NEAR(q.visibility_consistency, 1.0 - 1.6 / (1.6 * 6 + 2.0 * 12), 1e-12);
  EXPECT_EQ(q.floating_fragments, 1u);
}

TEST(SurfaceQuality, CoincidentVerticesJoinComponents) {
  // Two boxes touching along an edge, with their own vertices: one solid.
  PolygonMesh mesh;
  AddBox(mesh, Vec3(0, 0, 0), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(1, 1, 0), Vec3(2, 2, 1));
  Scene scene;
  const SurfaceQuality q = Measure(mesh, scene);
  EXPECT_EQ(q.components.size(), 1u);
  EXPECT_NEAR(q.enclosed_volume, 2.0, 1e-12);
}

TEST(SurfaceQuality, IdenticalForAnyThreadCount) {
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(2.0, -0.5, -0.5), Vec3(2.2, 0.5, 0.5));
  const Scene scene = CubeScene();
  const SurfaceQuality a = Measure(mesh, scene, 1);
  const SurfaceQuality b = Measure(mesh, scene, 2);
  EXPECT_EQ(a.data_fit, b.data_fit);
  EXPECT_EQ(a.visibility_consistency, b.visibility_consistency);
  EXPECT_EQ(a.components.size(), b.components.size());
}

FragmentRemoval Remove(const PolygonMesh& mesh, const Scene& scene) {
  Expected<FragmentRemoval> r = RemoveFloatingFragments(mesh, scene, kEps, {}, RunContext{});
  EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().message);
  return r ? std::move(*r) : FragmentRemoval{};
}

TEST(RemoveFloatingFragments, DropsTheFragmentsAndKeepsTheRestAsItWas) {
  // The cube, a floating box between two fragments of no support, in face order: fragment,
  // cube, fragment.
  PolygonMesh mesh;
  AddBox(mesh, Vec3(10, 10, 10), Vec3(10.5, 10.5, 10.5));
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(-10, 0, 0), Vec3(-9, 2, 1));
  const Scene scene = CubeScene();
  const FragmentRemoval r = Remove(mesh, scene);
  EXPECT_EQ(r.removed_components, 2u);
  EXPECT_NEAR(r.removed_volume, 0.125 + 2.0, 1e-12);
  EXPECT_EQ(r.removed_supported_segments, 0u);
  PolygonMesh cube;
  AddBox(cube, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_EQ(r.mesh.vertices, cube.vertices);
  EXPECT_EQ(r.mesh.face_indices, cube.face_indices);
  EXPECT_EQ(r.mesh.face_offsets, cube.face_offsets);
  const SurfaceQuality q = Measure(r.mesh, scene);
  EXPECT_EQ(q.floating_fragments, 0u);
  EXPECT_EQ(q.components.size(), 1u);
}

void ExpectSameFigures(const SurfaceQuality& a, const SurfaceQuality& b) {
  EXPECT_EQ(a.data_fit, b.data_fit);
  EXPECT_EQ(a.visibility_consistency, b.visibility_consistency);
  EXPECT_EQ(a.visibility_consistency_all, b.visibility_consistency_all);
  EXPECT_EQ(a.supported_segments, b.supported_segments);
  EXPECT_EQ(a.floating_fragments, b.floating_fragments);
  EXPECT_EQ(a.enclosed_volume, b.enclosed_volume);
  EXPECT_EQ(a.largest_component_share, b.largest_component_share);
  EXPECT_EQ(a.planes_off_surface, b.planes_off_surface);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (std::size_t c = 0; c < a.components.size(); ++c) {
    EXPECT_EQ(a.components[c].faces, b.components[c].faces) << c;
    EXPECT_EQ(a.components[c].volume, b.components[c].volume) << c;
    EXPECT_EQ(a.components[c].supported_length, b.components[c].supported_length) << c;
    EXPECT_EQ(a.components[c].supported_segments, b.components[c].supported_segments) << c;
    EXPECT_EQ(a.components[c].supported_lines, b.components[c].supported_lines) << c;
    EXPECT_EQ(a.components[c].floating, b.components[c].floating) << c;
  }
}

TEST(RemoveFloatingFragments, ItsFiguresAreThoseOfTheKeptSurface) {
  // Two cubes apart (both holding lines), a fragment in front of the +x face hiding its middle
  // line from its viewpoint, and one far off hiding nothing: the kept surface's figures, where
  // only the hidden line's segment is measured again, are a fresh measure's.
  Scene scene = CubeScene();
  const Scene right = CubeScene();
  const Vec3 shift(0, 10, 0);
  for (std::size_t i = 0; i < right.NumSegments(); ++i) {
    const SegmentId s(i);
    scene.segments.push_back(Segment3{right.segments[s].p1 + shift, right.segments[s].p2 + shift});
    scene.viewpoints.push_back(right.viewpoints[right.observations[s][0]] + shift);
    const std::array<ViewpointId, 1> row{ViewpointId(scene.viewpoints.size() - 1)};
    scene.observations.AddRow(row);
    scene.memberships.push_back(right.memberships[s]);
  }
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  AddBox(mesh, Vec3(3, -0.5, -0.5), Vec3(3.5, 0.5, 0.5));
  AddBox(mesh, Vec3(-1, 9, -1), Vec3(1, 11, 1));
  AddBox(mesh, Vec3(30, 30, 30), Vec3(31, 31, 31));
  const SurfaceQuality before = Measure(mesh, scene);
  EXPECT_LT(before.visibility_consistency, 1.0);
  const FragmentRemoval r = Remove(mesh, scene);
  EXPECT_EQ(r.removed_components, 2u);
  ASSERT_EQ(r.mesh.NumFaces(), 12u);
  const SurfaceQuality after = Measure(r.mesh, scene);
  EXPECT_NEAR(after.visibility_consistency, 1.0, 1e-12);
  ExpectSameFigures(r.quality, after);
}

TEST(RemoveFloatingFragments, KeepsTheInnerShellOfAVoid) {
  // A void inside the cube: its shell faces into the void (negative volume) and holds no line,
  // a floating fragment by the measure, but dropping it would fill the void.
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  PolygonMesh shell;
  AddBox(shell, Vec3(-0.2, -0.2, -0.2), Vec3(0.2, 0.2, 0.2));
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), shell.vertices.begin(), shell.vertices.end());
  for (std::size_t f = 0; f < shell.NumFaces(); ++f) {
    std::vector<std::uint32_t> reversed;
    for (std::uint32_t v : shell.Face(f)) reversed.insert(reversed.begin(), base + v);
    mesh.AddFace(reversed);
  }
  const Scene scene = CubeScene();
  const SurfaceQuality q = Measure(mesh, scene);
  ASSERT_EQ(q.components.size(), 2u);
  EXPECT_EQ(q.floating_fragments, 1u);
  EXPECT_NEAR(q.components[1].volume, -0.064, 1e-12);
  const FragmentRemoval r = Remove(mesh, scene);
  EXPECT_EQ(r.removed_components, 0u);
  EXPECT_EQ(r.mesh.face_indices, mesh.face_indices);
  ExpectSameFigures(r.quality, q);
}

TEST(RemoveFloatingFragments, LeavesAMeshWithoutFragmentsAndAMeshOfFragmentsOnly) {
  PolygonMesh cube;
  AddBox(cube, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const FragmentRemoval kept = Remove(cube, CubeScene());
  EXPECT_EQ(kept.removed_components, 0u);
  EXPECT_EQ(kept.mesh.vertices, cube.vertices);
  EXPECT_EQ(kept.mesh.face_indices, cube.face_indices);
  // No segment at all: every component is a fragment, and none is known to be the noise.
  PolygonMesh two = cube;
  AddBox(two, Vec3(5, 5, 5), Vec3(6, 6, 6));
  const FragmentRemoval whole = Remove(two, Scene{});
  EXPECT_EQ(whole.removed_components, 0u);
  EXPECT_EQ(whole.mesh.face_indices, two.face_indices);
}

TEST(SurfaceQuality, RejectsBadInput) {
  RunContext ctx;
  PolygonMesh empty;
  EXPECT_EQ(MeasureSurfaceQuality(empty, CubeScene(), kEps, {}, ctx).error().code,
            ErrorCode::kInvalidInput);
  PolygonMesh mesh;
  AddBox(mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_EQ(MeasureSurfaceQuality(mesh, CubeScene(), 0.0, {}, ctx).error().code,
            ErrorCode::kInvalidOptions);
  SurfaceQualityOptions bad;
  bad.samples_per_segment = 0;
  EXPECT_EQ(MeasureSurfaceQuality(mesh, CubeScene(), kEps, bad, ctx).error().code,
            ErrorCode::kInvalidOptions);
}

}  // namespace
}  // namespace linesurf::pipeline
