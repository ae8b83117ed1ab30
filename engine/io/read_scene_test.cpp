#include "engine/io/read_scene.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <fstream>

#include "engine/io/reference_json.h"
#include "tests/support/scene_compare.h"
#include "tests/support/test_paths.h"

namespace linesurf::io {
namespace {

std::filesystem::path WriteText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string Exact(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

/// Known camera centres of the fixtures (non-trivial decimals, one shared by two cameras).
const std::vector<Vec3> kCentres = {Vec3(1.5, -2.25, 10.125), Vec3(-3.0000000000000004, 4.1, 7.7),
                                    Vec3(1.5, -2.25, 10.125), Vec3(1e6 + 0.1, -2e6, 35.2)};

/// Two clusters: the first with 2 collinear segments seen by cameras 0, 1 and 0 again, the
/// second with 1 segment seen by cameras 2 and 3 (ids as given in `ids`).
std::string Line3dppText(const std::vector<long long>& ids) {
  auto id = [&](int k) { return std::to_string(ids[static_cast<std::size_t>(k)]); };
  return "2 0 0 0 1 0 0 1.5 0 0 2.0000000000000004 0 0 3 " + id(0) + " 4 10.5 20.25 30 40 " +
         id(1) + " 7 1 2 3 4.125 " + id(0) + " 9 5 6 7 8 \n" + "1 0.1 0.2 0.3 0.4 0.5 0.6 2 " +
         id(2) + " 0 100 200 300 400.5 " + id(3) + " 1 -1 -2 -3 -4\n";
}

std::filesystem::path WriteNvm(const std::filesystem::path& dir) {
  std::string text = "NVM_V3 FixedK 500 320 500 240 0\n\n" + std::to_string(kCentres.size()) + "\n";
  for (std::size_t c = 0; c < kCentres.size(); ++c) {
    text += "img " + std::to_string(c) + ".jpg 500 1 0 0 0 " + Exact(kCentres[c].x()) + " " +
            Exact(kCentres[c].y()) + " " + Exact(kCentres[c].z()) + " 0 0\n";
  }
  text += "\n2\n0 0 0 255 255 255 0\n1 1 1 255 255 255 0\n\n0\n";
  return WriteText(dir / "model.nvm", text);
}

/// COLMAP images.txt with IMAGE_IDs 11, 13, 17, 19 all on CAMERA_ID 1, rotated poses.
std::filesystem::path WriteColmap(const std::filesystem::path& dir) {
  const long long image_ids[] = {11, 13, 17, 19};
  std::string text =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n# Number of images: 4\n";
  for (std::size_t c = 0; c < kCentres.size(); ++c) {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.3 + 0.7 * static_cast<double>(c),
                                             Vec3(1, 2, 3).normalized()));
    const Vec3 t = -(q.toRotationMatrix() * kCentres[c]);
    text += std::to_string(image_ids[c]) + " " + Exact(q.w()) + " " + Exact(q.x()) + " " +
            Exact(q.y()) + " " + Exact(q.z()) + " " + Exact(t.x()) + " " + Exact(t.y()) + " " +
            Exact(t.z()) + " 1 image" + std::to_string(c) + ".png\n";
    text += c == 1 ? "\n" : "12.5 30.25 -1 40 50 7\n";  // an image without points: empty line
  }
  std::filesystem::create_directories(dir / "sparse");
  WriteText(dir / "sparse" / "images.txt", text);
  return dir / "sparse";
}

TEST(ReadScene, Line3dppWithNvmRoundTripsThroughJson) {
  const auto dir = testing::FreshTempDir();
  SceneReadOptions options;
  options.nvm = WriteNvm(dir);
  const auto txt = WriteText(dir / "Line3D++__W_FULL.txt", Line3dppText({0, 1, 2, 3}));
  const auto scene = ReadScene(txt, options);
  ASSERT_TRUE(scene) << scene.error().ToString();
  ASSERT_EQ(scene->NumSegments(), 3u);
  EXPECT_EQ(scene->viewpoints.size(), 3u);  // cameras 0 and 2 share a centre
  EXPECT_EQ(scene->viewpoints[ViewpointId(2u)], kCentres[3]);
  ASSERT_EQ(scene->observations[SegmentId(1u)].size(), 3u);  // the whole cluster's views
  EXPECT_EQ(scene->observations[SegmentId(1u)][2], ViewpointId(0u));
  ASSERT_EQ(scene->residuals.size(), 8u);
  EXPECT_EQ(scene->residuals[1][3], 4.125);  // not truncated to integers
  EXPECT_EQ(scene->segments[SegmentId(1u)].p2.x(), 2.0000000000000004);

  ASSERT_TRUE(WriteReferenceJson(*scene, dir / "out.json"));
  const auto back = ReadScene(dir / "out.json", SceneReadOptions{});
  ASSERT_TRUE(back) << back.error().ToString();
  ExpectScenesIdentical(*scene, *back);
}

TEST(ReadScene, Line3dppWithColmapUsesImageIdsAndRoundTrips) {
  const auto dir = testing::FreshTempDir();
  SceneReadOptions options;
  options.colmap = WriteColmap(dir);
  const auto txt = WriteText(dir / "lines.txt", Line3dppText({11, 13, 17, 19}));
  const auto scene = ReadScene(txt, options);
  ASSERT_TRUE(scene) << scene.error().ToString();
  ASSERT_EQ(scene->NumSegments(), 3u);
  // Centre = -R^T t recovers each image's own centre (all images share CAMERA_ID 1).
  EXPECT_LT((scene->viewpoints[ViewpointId(0u)] - kCentres[0]).norm(), 1e-9);
  EXPECT_LT((scene->viewpoints[ViewpointId(1u)] - kCentres[1]).norm(), 1e-9);
  const ViewpointId last = scene->observations[SegmentId(2u)][1];
  EXPECT_LT((scene->viewpoints[last] - kCentres[3]).norm(), 1e-6);

  ASSERT_TRUE(WriteReferenceJson(*scene, dir / "out.json"));
  const auto back = ReadScene(dir / "out.json", SceneReadOptions{});
  ASSERT_TRUE(back);
  ExpectScenesIdentical(*scene, *back);
}

TEST(ReadScene, JsonThroughReadSceneEqualsDirectRead) {
  const auto dir = testing::FreshTempDir();
  const auto path = WriteText(dir / "s.JSON", R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 1, 1],
      "pt_views": [[3, 3, 3]]}]})");
  const auto a = ReadScene(path, SceneReadOptions{});
  const auto b = ReadReferenceJson(path);
  ASSERT_TRUE(a && b);
  ExpectScenesIdentical(*a, *b);
}

TEST(ReadScene, ObjLinesGiveSegmentsWithoutViews) {
  const auto dir = testing::FreshTempDir();
  const auto path = WriteText(dir / "l.obj", "# ELSR\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 5 0\n"
                                             "l 1 2 3\nl -1 -4\n");
  const auto result = ReadSceneWithWarnings(path, SceneReadOptions{});
  ASSERT_TRUE(result) << result.error().ToString();
  ASSERT_EQ(result->scene.NumSegments(), 3u);
  EXPECT_EQ(result->scene.segments[SegmentId(2u)].p1, Vec3(0, 5, 0));
  EXPECT_EQ(result->scene.observations.NumItems(), 0u);
  EXPECT_EQ(result->scene.observations.NumRows(), 3u);
  EXPECT_EQ(result->warnings.size(), 1u);
}

struct BadCase {
  const char* name;
  std::string txt;
  const char* expected;
};

TEST(ReadScene, Line3dppErrorsNameFileAndLine) {
  const auto dir = testing::FreshTempDir();
  SceneReadOptions options;
  options.nvm = WriteNvm(dir);
  const BadCase cases[] = {
      {"unknown_cam", "1 0 0 0 1 1 1 1 7 0 1 2 3 4\n",
       "line 1: observation 0: camera id 7 is not in the camera model (4 cameras)"},
      {"short", "\n2 0 0 0 1 1 1 1\n", "line 2: 2 segments need 12 numbers"},
      {"obs_count", "1 0 0 0 1 1 1 2 0 0 1 2 3 4\n", "line 1: 2 observations need 12 values"},
      {"nan", "1 0 0 nan 1 1 1 0\n", "line 1: segment endpoint: 'nan' is not a finite number"},
  };
  for (const BadCase& c : cases) {
    const auto path = WriteText(dir / (std::string(c.name) + ".txt"), c.txt);
    const auto scene = ReadScene(path, options);
    ASSERT_FALSE(scene) << c.name;
    EXPECT_EQ(scene.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(scene.error().message.find(c.expected), std::string::npos) << scene.error().message;
    EXPECT_NE(scene.error().message.find(path.string()), std::string::npos);
  }
}

TEST(ReadScene, CameraModelErrors) {
  const auto dir = testing::FreshTempDir();
  const auto txt = WriteText(dir / "l.txt", "1 0 0 0 1 1 1 0\n");
  SceneReadOptions options;
  options.nvm = WriteText(dir / "bad.nvm", "NVM_V3\n\n2\nimg 500 1 0 0 0 1 2 3 0 0\n");
  auto scene = ReadScene(txt, options);
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("camera 1: unexpected end of file"), std::string::npos);
  options.nvm.clear();
  options.colmap = WriteText(dir / "images.txt", "# c\n1 1 0 0 0 x 0 0 1 a.png\n\n");
  scene = ReadScene(txt, options);
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("images.txt: line 2: expected 'IMAGE_ID"),
            std::string::npos)
      << scene.error().message;
}

TEST(ReadScene, OptionsAreCheckedAgainstTheFormat) {
  const auto dir = testing::FreshTempDir();
  const auto txt = WriteText(dir / "l.txt", "1 0 0 0 1 1 1 0\n");
  auto scene = ReadScene(txt, SceneReadOptions{});
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(scene.error().message.find("--nvm"), std::string::npos);
  SceneReadOptions options;
  options.nvm = dir / "x.nvm";
  scene = ReadScene(dir / "a.json", options);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().code, ErrorCode::kInvalidOptions);
  scene = ReadScene(dir / "a.las", SceneReadOptions{});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("unknown input format"), std::string::npos);
}

}  // namespace
}  // namespace linesurf::io
