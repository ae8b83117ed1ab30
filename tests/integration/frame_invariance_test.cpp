// The same scene in another frame (turned so that its up axis is not z, and scaled as another
// unit) gives the same mesh up to that move: the reconstruction works in the data's own frame
// (engine/pipeline/data_frame.h) and reports the data's up.

#include "engine/pipeline/reconstruct.h"

#include "tools/gen/synthesize.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace linesurf {
namespace {

constexpr double kScale = 37.1;
constexpr double kDegrees = 70.0;

synth::SyntheticScene Make(const std::string& family, double scale, double degrees) {
  synth::SynthSpec spec;
  spec.family = family;
  spec.seed = 1;
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  spec.scale = scale;
  spec.rotation_axis = {1.0, 2.0, 3.0};
  spec.rotation_degrees = degrees;
  auto s = synth::Synthesize(spec);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().ToString());
  return s ? std::move(s.value()) : synth::SyntheticScene{};
}

pipeline::ReconstructResult Reconstructed(const Scene& scene) {
  pipeline::ReconstructOptions o;  // detection, blocks and eps as by default
  o.seed = 3;
  auto r = pipeline::Reconstruct(scene, o, RunContext{});
  EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().ToString());
  return r ? std::move(r.value()) : pipeline::ReconstructResult{};
}

Eigen::Matrix3d Turn() {
  return Eigen::AngleAxisd(kDegrees * EIGEN_PI / 180.0, Vec3(1.0, 2.0, 3.0).normalized())
      .toRotationMatrix();
}

Vec3 ToVec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

TEST(FrameInvariance, TurnedAndScaledSceneGivesTheMovedMesh) {
  for (const char* family : {"house", "lshape", "city"}) {
    SCOPED_TRACE(family);
    const pipeline::ReconstructResult given = Reconstructed(Make(family, 1.0, 0.0).scene);
    const pipeline::ReconstructResult moved = Reconstructed(Make(family, kScale, kDegrees).scene);
    ASSERT_GT(given.mesh.NumFaces(), 0u);
    EXPECT_EQ(moved.stats.detection.planes, given.stats.detection.planes);
    ASSERT_EQ(moved.mesh.vertices.size(), given.mesh.vertices.size());
    ASSERT_EQ(moved.mesh.NumFaces(), given.mesh.NumFaces());
    EXPECT_EQ(moved.mesh.face_indices, given.mesh.face_indices);
    const Eigen::Matrix3d back = Turn().transpose() / kScale;
    double worst = 0.0;
    for (std::size_t v = 0; v < given.mesh.vertices.size(); ++v) {
      worst = std::max(worst, (back * moved.mesh.vertices[v] - given.mesh.vertices[v]).norm());
    }
    EXPECT_LT(worst, 1e-6) << "metres, the largest distance of a moved-back vertex";
    // The data's up is z as given, and the turned z when turned.
    EXPECT_TRUE(given.stats.frame.aligned);
    EXPECT_GT(ToVec(given.stats.frame.up).dot(Vec3::UnitZ()), 0.9999);
    EXPECT_GT(ToVec(moved.stats.frame.up).dot(Turn() * Vec3::UnitZ()), 0.9999);
  }
}

}  // namespace
}  // namespace linesurf
