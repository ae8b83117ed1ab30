// Hostile inputs through the library API (pipeline::Reconstruct, pipeline::EvaluateMesh,
// io::ReadMesh): an Error with the expected code, never a crash, an abort or a signal (a SIGFPE
// here kills the whole test executable).

#include "engine/io/mesh_io.h"
#include "engine/pipeline/reconstruct.h"
#include "tests/robustness/hostile_case.h"
#include "tests/support/test_paths.h"
#include "engine/pipeline/evaluate_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace linesurf::robustness {
namespace {

/// The 12 edges of the cube [-1, 1]^3 scaled by `scale` and moved by `offset`, each seen from
/// the 8 viewpoints at (+-4, +-4, +-4) (same transform).
Scene CubeScene(double scale = 1.0, double offset = 0.0) {
  Scene scene;
  for (int v = 0; v < 8; ++v) {
    scene.viewpoints.push_back(Vec3(v & 1 ? 4 : -4, v & 2 ? 4 : -4, v & 4 ? 4 : -4) * scale +
                               Vec3::Constant(offset));
  }
  std::array<ViewpointId, 8> all{};
  for (int v = 0; v < 8; ++v)
    all[static_cast<std::size_t>(v)] = ViewpointId(static_cast<std::size_t>(v));
  for (int axis = 0; axis < 3; ++axis) {
    for (int corner = 0; corner < 4; ++corner) {
      Vec3 a, b;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      a[axis] = -1.0;
      b[axis] = 1.0;
      a[u] = b[u] = corner & 1 ? 1.0 : -1.0;
      a[w] = b[w] = corner & 2 ? 1.0 : -1.0;
      scene.segments.push_back(
          Segment3{a * scale + Vec3::Constant(offset), b * scale + Vec3::Constant(offset)});
      scene.observations.AddRow(all);
    }
  }
  return scene;
}

pipeline::ReconstructOptions ExteriorEngineOptions() {
  pipeline::ReconstructOptions o;
  o.scene_mode = pipeline::SceneMode::kExterior;
  return o;
}

constexpr const char* kKind = "library API";

struct ApiCase {
  std::string name;
  Scene scene;
  pipeline::ReconstructOptions options;
  ErrorCode expected;
};

std::vector<ApiCase> ApiCases() {
  std::vector<ApiCase> cases;
  const auto add =
      [&](std::string name, Scene scene, pipeline::ReconstructOptions o, ErrorCode code) {
        cases.push_back({std::move(name), std::move(scene), std::move(o), code});
      };
  add("empty_scene", Scene{}, ExteriorEngineOptions(), ErrorCode::kInvalidInput);
  Scene nan = CubeScene();
  for (Segment3& s : nan.segments) s.p1.x() = std::numeric_limits<double>::quiet_NaN();
  add("every_segment_nan", nan, ExteriorEngineOptions(), ErrorCode::kInvalidInput);
  add("beyond_coordinate_bound",
      CubeScene(1.0, 1e13),
      ExteriorEngineOptions(),
      ErrorCode::kInvalidInput);
  Scene one = CubeScene();
  one.segments.resize(1);
  one.observations.Clear();
  one.observations.AddRow(std::array<ViewpointId, 1>{ViewpointId(std::size_t{0})});
  add("one_segment_no_plane", one, ExteriorEngineOptions(), ErrorCode::kDegenerate);
  pipeline::ReconstructOptions o = ExteriorEngineOptions();
  o.energy.sigma = 1e-9;
  add("sigma_1e_9", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.energy.weights.edge = 1e308;
  add("edge_weight_1e308", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.energy.weights.visibility = std::numeric_limits<double>::infinity();
  add("visibility_weight_inf", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.energy.weights.textural = 1e6;  // the largest weight, with sigma at its smallest allowed ratio
  o.energy.sigma = 1e-8;
  add("evidence_beyond_fixed_point", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.box_margin = -1.0;
  add("box_margin_negative", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.planes.epsilon = std::numeric_limits<double>::quiet_NaN();
  add("epsilon_nan", CubeScene(), o, ErrorCode::kInvalidOptions);
  o = ExteriorEngineOptions();
  o.use_given_planes = true;
  add("given_planes_none", CubeScene(), o, ErrorCode::kInvalidInput);
  return cases;
}

void PrintTo(const ApiCase& c, std::ostream* os) { *os << c.name; }

class LibraryApi : public ::testing::TestWithParam<ApiCase> {};

TEST_P(LibraryApi, ReconstructReturnsTheExpectedError) {
  const ApiCase& c = GetParam();
  RunContext ctx;
  RecordVerdict(kKind, ExitCodeOf(c.expected));
  const auto result = pipeline::Reconstruct(c.scene, c.options, ctx);
  ASSERT_FALSE(result.has_value()) << c.name << ": succeeded";
  EXPECT_EQ(result.error().code, c.expected) << result.error().ToString();
  EXPECT_FALSE(result.error().message.empty());
}

INSTANTIATE_TEST_SUITE_P(Hostile,
                         LibraryApi,
                         ::testing::ValuesIn(ApiCases()),
                         [](const auto& info) { return info.param.name; });

TEST(LibraryApi, ReconstructHandlesGeoreferencedOffsets) {
  RunContext ctx;
  for (const double offset : {0.0, 1e6, 1e9}) {
    RecordVerdict(kKind, 0);
    const auto result = pipeline::Reconstruct(CubeScene(1.0, offset), ExteriorEngineOptions(), ctx);
    ASSERT_TRUE(result.has_value()) << offset << ": " << result.error().ToString();
    EXPECT_TRUE(result->stats.surface.mesh_closed) << offset;
    EXPECT_NEAR(result->stats.surface.mesh_volume, 8.0, 8.0 * 1e-6) << offset;
  }
}

PolygonMesh CubeMesh(double scale) {
  PolygonMesh mesh;
  for (int v = 0; v < 8; ++v) {
    mesh.vertices.push_back(Vec3(v & 1 ? scale : 0, v & 2 ? scale : 0, v & 4 ? scale : 0));
  }
  const std::uint32_t faces[6][4] = {
      {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) mesh.AddFace(f);
  return mesh;
}

TEST(LibraryApi, EvaluateRefusesCoordinatesBeyondTheBoundInsteadOfTrapping) {
  EvaluationOptions o;
  o.samples_per_mesh = 1000;
  for (const double scale : {1e13, 1e80, 1e120, std::numeric_limits<double>::infinity()}) {
    RecordVerdict(kKind, 3);
    RecordVerdict(kKind, 3);
    const auto result = pipeline::EvaluateMesh(CubeMesh(scale), CubeMesh(1.0), o, std::nullopt);
    ASSERT_FALSE(result.has_value()) << scale;
    EXPECT_EQ(result.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(result.error().message.find("result mesh: vertex 1"), std::string::npos)
        << result.error().ToString();
    const auto gt = pipeline::EvaluateMesh(CubeMesh(1.0), CubeMesh(scale), o, std::nullopt);
    ASSERT_FALSE(gt.has_value()) << scale;
    EXPECT_NE(gt.error().message.find("ground truth mesh: vertex 1"), std::string::npos);
  }
  RecordVerdict(kKind, 0);
  const auto big = pipeline::EvaluateMesh(CubeMesh(1e11), CubeMesh(1e11), o, std::nullopt);
  ASSERT_TRUE(big.has_value()) << big.error().ToString();
  EXPECT_DOUBLE_EQ(big->precision.back(), 1.0);
}

TEST(LibraryApi, MeshReadersRefuseCoordinatesBeyondTheBound) {
  const auto dir = testing::FreshTempDir();
  for (const char* ext : {".off", ".obj", ".ply"}) {
    RecordVerdict(kKind, 3);
    const auto path = dir / (std::string("cube") + ext);
    ASSERT_TRUE(io::WriteMesh(CubeMesh(1e13), path).has_value());
    const auto read = io::ReadMesh(path);
    ASSERT_FALSE(read.has_value()) << ext;
    EXPECT_EQ(read.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(read.error().message.find(path.string() + ": vertex 1: coordinate 1e+13"),
              std::string::npos)
        << read.error().ToString();
  }
}

}  // namespace
}  // namespace linesurf::robustness
