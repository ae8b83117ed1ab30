#include "engine/io/vertex_groups_write.h"

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace linesurf::io {
namespace {

TEST(VertexGroups, PlanesListTheirInliersEndpointsInWorldCoordinates) {
  Scene scene;
  scene.world_from_local.translation = Vec3(100, 0, 0);
  scene.segments.push_back({Vec3(0, 0, 0), Vec3(1, 0, 0)});  // on both planes
  scene.segments.push_back({Vec3(0, 0, 1), Vec3(0, 0, 2)});  // on plane 1
  scene.segments.push_back({Vec3(5, 5, 5), Vec3(6, 5, 5)});  // on none
  scene.planes.push_back({Vec3(0, 0, 0), Vec3(0, 0, 1)});
  scene.planes.push_back({Vec3(0, 0, 0), Vec3(0, 1, 0)});
  PlaneMembership both, one;
  both.Add(PlaneId(0u));
  both.Add(PlaneId(1u));
  one.Add(PlaneId(1u));
  scene.memberships.push_back(both);
  scene.memberships.push_back(one);
  scene.memberships.push_back(PlaneMembership{});
  const auto dir = testing::FreshTempDir();
  ASSERT_TRUE(WriteVertexGroups(scene, dir / "p.vg"));
  std::stringstream text;
  text << std::ifstream(dir / "p.vg").rdbuf();
  const std::string vg = text.str();
  EXPECT_EQ(vg.rfind("num_points: 6\n100.0 0.0 0.0\n101.0 0.0 0.0\n", 0), 0u) << vg;
  EXPECT_NE(vg.find("num_normals: 6\n0.0 0.0 1.0\n0.0 0.0 1.0\n0.0 1.0 0.0\n"), std::string::npos);
  EXPECT_NE(vg.find("num_groups: 2\n"), std::string::npos);
  // Plane 1 (y = 0): d = 0; its inliers are segments 0 and 1.
  EXPECT_NE(vg.find("group_parameters: 0.0 1.0 0.0 -0.0\ngroup_label: plane_1\n"
                    "group_color: 0.5 0.5 0.5\ngroup_num_point: 4\n0 1 2 3\nnum_children: 0\n"),
            std::string::npos)
      << vg;
  EXPECT_NE(vg.find("group_num_point: 2\n0 1\n"), std::string::npos);
}

TEST(VertexGroups, UnwritablePathIsAnError) {
  const Status s = WriteVertexGroups(Scene{}, "/nonexistent-dir/p.vg");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(s.error().message.find("/nonexistent-dir/p.vg"), std::string::npos);
}

}  // namespace
}  // namespace linesurf::io
