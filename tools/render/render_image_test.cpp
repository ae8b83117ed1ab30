#include "tools/render/render_image.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <iterator>

#include "tests/support/test_paths.h"
#include "tools/render/write_png.h"

namespace linesurf {
namespace {

Mesh UnitCube() {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  }
  const std::array<std::array<std::uint32_t, 4>, 6> faces{{
      {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    mesh.face_indices.insert(mesh.face_indices.end(), f.begin(), f.end());
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
  }
  return mesh;
}

/// The cube's 12 edges as segments: bottom ones structural (two planes), top ones textural (one
/// plane), verticals on none.
SceneData CubeEdges() {
  SceneData scene;
  const Mesh cube = UnitCube();
  const std::array<std::array<int, 2>, 12> edges{{{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                                  {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  scene.planes.resize(2);
  scene.has_memberships = true;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto s = static_cast<std::uint32_t>(e);
    scene.segments.push_back({cube.vertices[edges[e][0]], cube.vertices[edges[e][1]]});
    const int count = e < 4 ? 2 : e < 8 ? 1 : 0;
    for (int k = 0; k < count; ++k) scene.memberships.push_back({s, static_cast<std::uint32_t>(k)});
  }
  return scene;
}

std::size_t CountPixels(const Image& image, const std::array<std::uint8_t, 3>& colour, int x0, int x1) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = x0; x < x1; ++x) n += image.Pixel(x, y) == colour ? 1 : 0;
  }
  return n;
}

TEST(RenderImage, MeshPanelIsShadedAndFramed) {
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  const Mesh cube = UnitCube();
  const auto image = RenderImage(nullptr, &cube, options);
  ASSERT_TRUE(image) << image.error().ToString();
  ASSERT_EQ(image->width, 160);
  ASSERT_EQ(image->height, 120);
  const std::size_t background = CountPixels(*image, kColourBackground, 0, 160);
  EXPECT_LT(background, 160U * 120U * 9 / 10);  // the cube covers a good part of the view
  EXPECT_GT(background, 160U * 120U / 4);       // and fits inside it
  EXPECT_EQ(image->Pixel(0, 0), kColourBackground);
  EXPECT_NE(image->Pixel(80, 60), kColourBackground);  // the centre shows the cube
}

TEST(RenderImage, LinesAndMeshSideBySideWithMembershipColours) {
  RenderOptions options;
  options.width = 320;
  options.height = 160;
  options.supersample = 1;  // exact colours, no blending
  options.line_width = 3.0;
  const Mesh cube = UnitCube();
  const SceneData edges = CubeEdges();
  const auto image = RenderImage(&edges, &cube, options);
  ASSERT_TRUE(image) << image.error().ToString();
  ASSERT_EQ(image->width, 320);
  // The left panel holds lines: some nearly pure red (structural) and blue (textural) pixels.
  std::size_t reddish = 0;
  std::size_t bluish = 0;
  for (int y = 0; y < image->height; ++y) {
    for (int x = 0; x < 160; ++x) {
      const auto p = image->Pixel(x, y);
      reddish += (p[0] > 180 && p[1] < 140 && p[2] < 140) ? 1 : 0;
      bluish += (p[2] > 180 && p[0] < 150) ? 1 : 0;
    }
  }
  EXPECT_GT(reddish, 20U);
  EXPECT_GT(bluish, 20U);
  // The right panel holds the shaded cube.
  EXPECT_LT(CountPixels(*image, kColourBackground, 160, 320), 160U * 160U * 9 / 10);
}

TEST(RenderImage, PngIsWrittenWithTheRightSizeAndDeterministicBytes) {
  RenderOptions options;
  options.width = 200;
  options.height = 100;
  options.view = "top";
  const Mesh cube = UnitCube();
  const SceneData edges = CubeEdges();
  const auto dir = testing::FreshTempDir();
  std::string bytes[2];
  for (int run = 0; run < 2; ++run) {
    const auto image = RenderImage(&edges, &cube, options);
    ASSERT_TRUE(image);
    const auto path = dir / ("run" + std::to_string(run) + ".png");
    ASSERT_TRUE(WritePng(*image, path));
    std::ifstream in(path, std::ios::binary);
    bytes[run].assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes[0].size(), 33U);
  EXPECT_EQ(bytes[0].substr(1, 3), "PNG");
  const auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[0][at + k]);
    return v;
  };
  EXPECT_EQ(be32(16), 200U);  // IHDR width
  EXPECT_EQ(be32(20), 100U);  // IHDR height
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(RenderImage, RejectsNothingToDrawAndBadOptions) {
  EXPECT_EQ(RenderImage(nullptr, nullptr, RenderOptions{}).error().code, ErrorCode::kInvalidInput);
  RenderOptions options;
  options.view = "sideways";
  const Mesh cube = UnitCube();
  EXPECT_EQ(RenderImage(nullptr, &cube, options).error().code, ErrorCode::kInvalidOptions);
  options.view = "iso";
  options.width = 4;
  EXPECT_EQ(RenderImage(nullptr, &cube, options).error().code, ErrorCode::kInvalidOptions);
  options.width = 160;
  SceneData edges = CubeEdges();
  edges.memberships.push_back({99, 0});
  const auto bad_membership = RenderImage(&edges, nullptr, options);
  ASSERT_FALSE(bad_membership);
  EXPECT_EQ(bad_membership.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(bad_membership.error().message.find("segment 99"), std::string::npos);
}

}  // namespace
}  // namespace linesurf
