#include "engine/io/cityjson_write.h"

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

namespace linesurf::io {
namespace {

/// An axis-aligned box [lo, hi] with quad faces counter-clockwise seen from outside; `inward`
/// reverses every face (the inside of a room).
void AddBox(PolygonMesh& mesh, const Vec3& lo, const Vec3& hi, bool inward = false) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back(
        Vec3((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z()));
  }
  const std::uint32_t faces[6][4] = {
      {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    std::uint32_t face[4];
    for (int k = 0; k < 4; ++k) face[k] = base + f[inward ? 3 - k : k];
    mesh.AddFace(face);
  }
}

nlohmann::json Read(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CityJson, ExtensionsSelectTheWriter) {
  EXPECT_TRUE(IsCityJsonPath("a/m.city.json"));
  EXPECT_TRUE(IsCityJsonPath("M.CityJSON"));
  EXPECT_FALSE(IsCityJsonPath("m.json"));
  EXPECT_FALSE(IsCityJsonPath("city.json.ply"));
}

TEST(CityJson, OneBuildingPerComponentWithPlaneSurfaces) {
  PolygonMesh mesh;
  const Vec3 offset(84000.25, 447000.5, 3.0);  // georeferenced coordinates
  AddBox(mesh, offset + Vec3(0, 0, 0), offset + Vec3(10, 8, 6));
  AddBox(mesh, offset + Vec3(20, 0, 0), offset + Vec3(24, 4, 3));
  // Planes of the first box's roof (z = 6) and one wall (x = 10); the normal's sign is free.
  const std::vector<Plane3> planes = {{offset + Vec3(0, 0, 6), Vec3(0, 0, -1)},
                                      {offset + Vec3(10, 0, 0), Vec3(1, 0, 0)}};
  const auto dir = testing::FreshTempDir();
  ASSERT_TRUE(WriteCityJson(mesh, planes, dir / "m.city.json"));
  const nlohmann::json city = Read(dir / "m.city.json");
  EXPECT_EQ(city["type"], "CityJSON");
  EXPECT_EQ(city["version"], "1.1");
  ASSERT_EQ(city["CityObjects"].size(), 2u);
  ASSERT_EQ(city["vertices"].size(), 16u);
  // Dequantised vertices are the mesh's within one quantum.
  const auto& scale = city["transform"]["scale"];
  const auto& translate = city["transform"]["translate"];
  for (std::size_t v = 0; v < 16; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = city["vertices"][v][k].get<long long>() * scale[k].get<double>() +
                       translate[k].get<double>();
      EXPECT_NEAR(x, mesh.vertices[v][k], scale[k].get<double>()) << v;
    }
  }
  const auto& first = city["CityObjects"]["building_0"];
  EXPECT_EQ(first["type"], "Building");
  const auto& geometry = first["geometry"][0];
  EXPECT_EQ(geometry["type"], "Solid");
  EXPECT_EQ(geometry["lod"], "2");
  ASSERT_EQ(geometry["boundaries"].size(), 1u);     // one shell
  ASSERT_EQ(geometry["boundaries"][0].size(), 6u);  // six faces
  EXPECT_EQ(geometry["boundaries"][0][1][0], nlohmann::json({4, 5, 7, 6}));
  // Face 1 is the roof on plane 0, face 5 the wall on plane 1: their surfaces carry the plane.
  const auto& semantics = geometry["semantics"];
  const auto& values = semantics["values"][0];
  const auto& roof = semantics["surfaces"][values[1].get<std::size_t>()];
  EXPECT_EQ(roof["type"], "RoofSurface");
  EXPECT_EQ(roof["plane_index"], 0);
  EXPECT_EQ(roof["plane"], nlohmann::json({-0.0, -0.0, -1.0, offset.z() + 6.0}));
  const auto& wall = semantics["surfaces"][values[5].get<std::size_t>()];
  EXPECT_EQ(wall["type"], "WallSurface");
  EXPECT_EQ(wall["plane_index"], 1);
  const auto& ground = semantics["surfaces"][values[0].get<std::size_t>()];
  EXPECT_EQ(ground["type"], "GroundSurface");
  EXPECT_FALSE(ground.contains("plane_index"));
  // The second box is on neither plane (its x = 24 wall is parallel to plane 1, 14 m away).
  for (const auto& s : city["CityObjects"]["building_1"]["geometry"][0]["semantics"]["surfaces"]) {
    EXPECT_FALSE(s.contains("plane_index")) << s;
  }
}

TEST(CityJson, InwardComponentIsACompositeSurface) {
  PolygonMesh mesh;
  AddBox(mesh, Vec3(0, 0, 0), Vec3(5, 4, 3), /*inward=*/true);
  const auto dir = testing::FreshTempDir();
  ASSERT_TRUE(WriteCityJson(mesh, {}, dir / "room.cityjson"));
  const nlohmann::json city = Read(dir / "room.cityjson");
  const auto& geometry = city["CityObjects"]["building_0"]["geometry"][0];
  EXPECT_EQ(geometry["type"], "CompositeSurface");
  EXPECT_EQ(geometry["boundaries"].size(), 6u);
  EXPECT_EQ(geometry["semantics"]["values"].size(), 6u);
}

TEST(CityJson, EmptyMeshAndBadFaces) {
  const auto dir = testing::FreshTempDir();
  ASSERT_TRUE(WriteCityJson(PolygonMesh{}, {}, dir / "e.city.json"));
  EXPECT_TRUE(Read(dir / "e.city.json")["CityObjects"].empty());
  PolygonMesh bad;
  bad.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const std::uint32_t face[] = {0, 1, 5};
  bad.AddFace(face);
  const Status s = WriteCityJson(bad, {}, dir / "b.city.json");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("face 0: vertex 5 out of range"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "b.city.json"));
}

}  // namespace
}  // namespace linesurf::io
