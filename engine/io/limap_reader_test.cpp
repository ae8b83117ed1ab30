#include "engine/io/limap_reader.h"

#include "engine/core/exception.h"
#include "engine/io/read_scene.h"
#include "tests/support/sfm_fixtures.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

namespace linesurf::io {
namespace {

/// Two tracks: the first supported twice by image 7 and once by image 9, the second by 9 only.
constexpr const char* kTracks =
    "2\n"
    "0 3 2\n0.0000000000 0.0000000000 0.0000000000\n1.5000000000 0.0000000000 0.2500000000\n"
    "7 9 7 \n4 8 15 \n"
    "1 1 1\n-1.0 2.0 3.0\n-1.0 2.0 4.0\n9 \n16 \n";

const CameraCentres kTrackCameraCentres = {{7, Vec3(10, 0, 0)}, {9, Vec3(0, 10, 0)}};

std::string ReadTracksError(const std::string& text) {
  const auto dir = testing::FreshTempDir();
  testing::WriteFixture(dir / "alltracks.txt", text);
  try {
    ReadLimapTracks(dir / "alltracks.txt", kTrackCameraCentres);
  } catch (const LinesurfException& e) {
    EXPECT_NE(e.error().message.find("alltracks.txt: line "), std::string::npos);
    return e.error().message;
  }
  return "";
}

TEST(LimapReader, TracksBecomeSegmentsSeenFromTheirImages) {
  const auto dir = testing::FreshTempDir();
  testing::WriteFixture(dir / "alltracks.txt", kTracks);
  const Scene scene = ReadLimapTracks(dir / "alltracks.txt", kTrackCameraCentres);
  ASSERT_EQ(scene.NumSegments(), 2u);
  EXPECT_EQ(scene.segments[SegmentId(0u)].p2, Vec3(1.5, 0, 0.25));
  EXPECT_EQ(scene.segments[SegmentId(1u)].p1, Vec3(-1, 2, 3));
  ASSERT_EQ(scene.viewpoints.size(), 2u);
  EXPECT_EQ(scene.viewpoints[ViewpointId(1u)], Vec3(0, 10, 0));
  ASSERT_EQ(scene.observations[SegmentId(0u)].size(), 3u);  // repeats left to sanitation
  EXPECT_EQ(scene.observations[SegmentId(0u)][2], ViewpointId(0u));
  EXPECT_EQ(scene.observations[SegmentId(1u)][0], ViewpointId(1u));
  EXPECT_TRUE(scene.residuals.empty());
}

TEST(LimapReader, ErrorsNameTheLine) {
  EXPECT_NE(ReadTracksError("1\n0 1 1\n0 0 0\n1 1 1\n8 \n0 \n")
                .find("line 5: track 0: image id 8 is not in the camera model (2 cameras)"),
            std::string::npos);
  EXPECT_NE(ReadTracksError("1\n0 2 2\n0 0 0\n1 1 1\n7 7 \n0 1 \n")
                .find("line 5: track 0: 1 distinct image ids, the track header announces 2"),
            std::string::npos);
  EXPECT_NE(
      ReadTracksError("1\n0 1 1\n0 0 0\n1 nan 1\n7 \n0 \n").find("line 4: track 0: expected 3"),
      std::string::npos);
  EXPECT_NE(
      ReadTracksError("2\n0 1 1\n0 0 0\n1 1 1\n7 \n0 \n").find("line 7: file ends before the next"),
      std::string::npos);
  EXPECT_NE(
      ReadTracksError("1\n0 2 1\n0 0 0\n1 1 1\n7 \n0 \n").find("line 5: track 0: 2 image ids"),
      std::string::npos);
  EXPECT_NE(ReadTracksError("1\n0 1 1\n0 0 0\n1 1 1\n7 \n0 \n5\n").find("line 7: text after the 1"),
            std::string::npos);
}

TEST(LimapReader, ReadSceneTellsLimapFromLine3dppByTheFirstLine) {
  const auto dir = testing::FreshTempDir();
  testing::WriteFixture(dir / "alltracks.txt", std::string("\n") + kTracks);
  testing::WriteFixture(dir / "l3d.txt", "1 0 0 0 1 1 1 1 7 0 1 2 3 4\n");
  EXPECT_EQ(ResolveSceneFormat(dir / "alltracks.txt", {}), SceneFormat::kLimapTracks);
  EXPECT_EQ(ResolveSceneFormat(dir / "l3d.txt", {}), SceneFormat::kLine3dpp);
  EXPECT_EQ(ResolveSceneFormat(dir / "missing.txt", {}), SceneFormat::kLine3dpp);

  Scene cameras;
  cameras.viewpoints.push_back(Vec3(10, 0, 0));
  const auto list = testing::CamerasFor(cameras, 7, 1);
  testing::WriteFixture(dir / "images.bin", testing::ColmapImagesBinary(list));
  SceneReadOptions options;
  options.colmap = dir;
  auto scene = ReadScene(dir / "alltracks.txt", options);
  ASSERT_FALSE(scene);  // image 9 is not in this one-image model
  EXPECT_NE(scene.error().message.find("line 6: track 0: image id 9"), std::string::npos)
      << scene.error().message;
  scene = ReadScene(dir / "alltracks.txt", SceneReadOptions{});
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(scene.error().message.find("LIMAP alltracks .txt input needs"), std::string::npos);
}

}  // namespace
}  // namespace linesurf::io
