#include "engine/io/camera_centres.h"

#include "engine/core/exception.h"
#include "tests/support/sfm_fixtures.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

namespace linesurf::io {
namespace {

using testing::FixtureCamera;
using testing::WriteFixture;

/// Awkward centres (non-dyadic, huge, negative zero) and non-contiguous IMAGE_IDs.
std::vector<FixtureCamera> Cameras(long long first_id, long long step) {
  Scene scene;
  for (const Vec3& c : {Vec3(1.5, -2.25, 10.125),
                        Vec3(-3.0000000000000004, 4.1, 7.7),
                        Vec3(1e6 + 0.1, -2e6, 35.2),
                        Vec3(-0.0, 0.3, -7.0)}) {
    scene.viewpoints.push_back(c);
  }
  return testing::CamerasFor(scene, first_id, step);
}

void ExpectCentres(const CameraCentres& read, const std::vector<FixtureCamera>& cameras) {
  ASSERT_EQ(read.size(), cameras.size());
  for (const FixtureCamera& c : cameras) {
    ASSERT_TRUE(read.count(c.id)) << c.id;
    EXPECT_EQ(read.at(c.id), c.centre) << c.id;  // half turns: exact
  }
}

/// The message of the kInvalidInput error `fn` throws ("" when it does not throw).
template <typename Fn>
std::string ErrorOf(Fn&& fn) {
  try {
    fn();
  } catch (const LinesurfException& e) {
    EXPECT_EQ(e.error().code, ErrorCode::kInvalidInput);
    return e.error().message;
  }
  return "";
}

TEST(CameraCentres, NvmKeysCentresByIndex) {
  const auto dir = testing::FreshTempDir();
  const auto cameras = Cameras(0, 1);
  WriteFixture(dir / "m.nvm", testing::NvmText(cameras));
  ExpectCentres(ReadNvmCameraCentres(dir / "m.nvm"), cameras);
}

TEST(CameraCentres, ColmapTextAndBinaryGiveTheSameCentres) {
  const auto dir = testing::FreshTempDir();
  const auto cameras = Cameras(11, 7);
  std::filesystem::create_directories(dir / "text");
  std::filesystem::create_directories(dir / "bin");
  WriteFixture(dir / "text" / "images.txt", testing::ColmapImagesText(cameras));
  WriteFixture(dir / "text" / "cameras.txt", testing::ColmapCamerasText());
  WriteFixture(dir / "bin" / "images.bin", testing::ColmapImagesBinary(cameras));
  WriteFixture(dir / "bin" / "cameras.bin", testing::ColmapCamerasBinary());
  ExpectCentres(ReadColmapCameraCentres(dir / "text"), cameras);
  ExpectCentres(ReadColmapCameraCentres(dir / "text" / "images.txt"), cameras);
  ExpectCentres(ReadColmapCameraCentres(dir / "bin"), cameras);
  ExpectCentres(ReadColmapCameraCentres(dir / "bin" / "images.bin"), cameras);
}

TEST(CameraCentres, ColmapDirectoryPrefersTheBinaryModel) {
  const auto dir = testing::FreshTempDir();
  const auto cameras = Cameras(1, 1);
  WriteFixture(dir / "images.bin", testing::ColmapImagesBinary(cameras));
  WriteFixture(dir / "images.txt", "not a model\n");
  ExpectCentres(ReadColmapCameraCentres(dir), cameras);
}

TEST(CameraCentres, ColmapRotatedPosesGiveTheirCentres) {
  const auto dir = testing::FreshTempDir();
  auto cameras = Cameras(3, 2);
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    cameras[k].rotation =
        Eigen::AngleAxisd(0.3 + 0.7 * static_cast<double>(k), Vec3(1, 2, 3).normalized());
  }
  WriteFixture(dir / "images.bin", testing::ColmapImagesBinary(cameras));
  const CameraCentres read = ReadColmapCameraCentres(dir);
  for (const FixtureCamera& c : cameras) {
    EXPECT_LT((read.at(c.id) - c.centre).norm(), 1e-9 * (1.0 + c.centre.norm())) << c.id;
  }
}

TEST(CameraCentres, BinaryErrorsNameFileImageAndByte) {
  const auto dir = testing::FreshTempDir();
  const std::string full = testing::ColmapImagesBinary(Cameras(1, 1));
  WriteFixture(dir / "images.bin", full.substr(0, full.size() - 5));
  EXPECT_NE(ErrorOf([&] { ReadColmapCameraCentres(dir); }).find("images.bin: image 3 (byte "),
            std::string::npos);
  WriteFixture(dir / "images.bin", full + "xyz");
  EXPECT_NE(ErrorOf([&] { ReadColmapCameraCentres(dir); }).find("3 bytes after the 4 announced"),
            std::string::npos);
  WriteFixture(dir / "images.bin", std::string(4, '\0'));
  EXPECT_NE(ErrorOf([&] { ReadColmapCameraCentres(dir); }).find("shorter than its 8-byte"),
            std::string::npos);
}

TEST(CameraCentres, ImagesMustUseCamerasOfTheModel) {
  const auto dir = testing::FreshTempDir();
  std::string cameras_bin = testing::ColmapCamerasBinary();
  cameras_bin[8] = 2;  // the one camera is CAMERA_ID 2, the images use 1
  WriteFixture(dir / "images.bin", testing::ColmapImagesBinary(Cameras(1, 1)));
  WriteFixture(dir / "cameras.bin", cameras_bin);
  EXPECT_NE(ErrorOf([&] {
              ReadColmapCameraCentres(dir);
            }).find("images.bin: image 0 (byte 8): CAMERA_ID 1 is not in"),
            std::string::npos);
  cameras_bin[12] = 42;  // MODEL_ID
  WriteFixture(dir / "cameras.bin", cameras_bin);
  EXPECT_NE(ErrorOf([&] {
              ReadColmapCameraCentres(dir);
            }).find("cameras.bin: camera 0 (byte 8): unknown MODEL_ID 42"),
            std::string::npos);
  WriteFixture(dir / "images.txt", testing::ColmapImagesText(Cameras(1, 1)));
  WriteFixture(dir / "cameras.txt", "# none\n3 PINHOLE 640 480 1 1 1 1\n");
  EXPECT_NE(ErrorOf([&] {
              ReadColmapCameraCentres(dir / "images.txt");
            }).find("images.txt: line 4: CAMERA_ID 1 is not in"),
            std::string::npos);
}

TEST(CameraCentres, RepeatedImageIdIsAnError) {
  const auto dir = testing::FreshTempDir();
  WriteFixture(dir / "images.bin", testing::ColmapImagesBinary(Cameras(5, 0)));
  EXPECT_NE(ErrorOf([&] { ReadColmapCameraCentres(dir); }).find("IMAGE_ID 5 repeated"),
            std::string::npos);
}

}  // namespace
}  // namespace linesurf::io
