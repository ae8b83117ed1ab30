#include "engine/io/reference_json.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/scene_compare.h"
#include "tests/support/test_paths.h"

namespace linesurf::io {
namespace {

std::filesystem::path WriteText(const std::filesystem::path& dir, const std::string& name,
                                const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ReferenceJson, ReadsAndalusianCounts) {
  LINESURF_REQUIRE_ANDALUSIAN(input);
  const auto scene = ReadReferenceJson(input);
  ASSERT_TRUE(scene) << scene.error().ToString();
  EXPECT_EQ(scene->NumSegments(), 14503u);
  EXPECT_EQ(scene->viewpoints.size(), 249u);
  EXPECT_EQ(scene->planes.size(), 148u);
  EXPECT_EQ(scene->observations.NumItems(), 14503u);
  ASSERT_EQ(scene->memberships.size(), 14503u);
  std::size_t counts[3] = {0, 0, 0};
  for (const auto& m : scene->memberships) ++counts[m.count];
  EXPECT_EQ(counts[0], 1046u);
  EXPECT_EQ(counts[1], 6440u);
  EXPECT_EQ(counts[2], 7017u);
  EXPECT_TRUE(scene->residuals.empty());
}

TEST(ReferenceJson, AndalusianRoundTripKeepsEveryValueAndBytes) {
  LINESURF_REQUIRE_ANDALUSIAN(input);
  const auto dir = testing::FreshTempDir();
  const auto first = ReadReferenceJson(input);
  ASSERT_TRUE(first);
  ASSERT_TRUE(WriteReferenceJson(*first, dir / "a.json"));
  const auto second = ReadReferenceJson(dir / "a.json");
  ASSERT_TRUE(second) << second.error().ToString();
  ExpectScenesIdentical(*first, *second);
  ASSERT_TRUE(WriteReferenceJson(*second, dir / "b.json"));
  EXPECT_EQ(ReadBytes(dir / "a.json"), ReadBytes(dir / "b.json"));
}

TEST(ReferenceJson, SmallRoundTripWithResidualsAndExtraFields) {
  const auto dir = testing::FreshTempDir();
  const auto path = WriteText(dir, "in.json", R"({"original_L3Dpp_file": "a \"b\".txt",
    "lines": [
      {"pt1": [0.1, -0.0, 1e300], "pt2": [1, 2, 3], "pt_views": [[5, 5, 5], [0.3, 0.2, 0.1]],
       "plane_index": [1, 0], "residual_per_pt_view": [[1.5, 2, 3, 4], [5, 6, 7, 8.25]]},
      {"pt1": [4e-320, 2, 3], "pt2": [1, 2, 4.000000000000001], "pt_views": [[5, 5, 5.0]],
       "plane_index": [], "residual_per_pt_view": [[0, 0, 1, 1]]}],
    "planes": [{"inlier": [0, 0, 0], "normal": [0, 0, 1]},
               {"normal": [0.6, 0.8, 0], "inlier": [1, 1, 1]}]})");
  const auto first = ReadReferenceJson(path);
  ASSERT_TRUE(first) << first.error().ToString();
  ASSERT_EQ(first->NumSegments(), 2u);
  EXPECT_EQ(first->viewpoints.size(), 2u);  // [5,5,5] shared by both lines
  EXPECT_EQ(first->observations[SegmentId(1u)][0], ViewpointId(0u));
  EXPECT_EQ(first->residuals.size(), 3u);
  EXPECT_TRUE(std::signbit(first->segments[SegmentId(0u)].p1.y()));
  ASSERT_EQ(first->extra_fields.size(), 1u);
  EXPECT_EQ(first->extra_fields[0].second, "a \"b\".txt");
  EXPECT_EQ(first->memberships[SegmentId(0u)].planes[0], PlaneId(1u));
  ASSERT_TRUE(WriteReferenceJson(*first, dir / "out.json"));
  const auto second = ReadReferenceJson(dir / "out.json");
  ASSERT_TRUE(second) << second.error().ToString();
  ExpectScenesIdentical(*first, *second);
  EXPECT_EQ(ReadBytes(dir / "out.json").find("null"), std::string::npos);
}

TEST(ReferenceJson, WriterAppliesWorldFromLocal) {
  const auto dir = testing::FreshTempDir();
  Scene scene;
  scene.segments.push_back(Segment3{Vec3(0, 0, 0), Vec3(1, 0, 0)});
  scene.viewpoints.push_back(Vec3(0, 1, 0));
  scene.observations.AddRow(std::vector<ViewpointId>{ViewpointId(0u)});
  scene.world_from_local.translation = Vec3(1e6, 2e6, 0);
  ASSERT_TRUE(WriteReferenceJson(scene, dir / "w.json"));
  const auto back = ReadReferenceJson(dir / "w.json");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->segments[SegmentId(0u)].p2, Vec3(1e6 + 1, 2e6, 0));
  EXPECT_EQ(back->viewpoints[ViewpointId(0u)], Vec3(1e6, 2e6 + 1, 0));
  EXPECT_TRUE(back->world_from_local.translation.isZero());
  EXPECT_FALSE(back->HasMemberships());
}

TEST(ReferenceJson, PlanesOnlyFileHasNoSegments) {
  const auto dir = testing::FreshTempDir();
  const auto scene = ReadReferenceJson(
      WriteText(dir, "p.json", R"({"planes": [{"inlier": [0, 0, 0], "normal": [1, 0, 0]}]})"));
  ASSERT_TRUE(scene) << scene.error().ToString();
  EXPECT_EQ(scene->NumSegments(), 0u);
  EXPECT_EQ(scene->planes.size(), 1u);
}

TEST(ReferenceJson, PlaneIndexRepeatsAndExtrasAreWarnedNotFatal) {
  const auto dir = testing::FreshTempDir();
  const auto result = ReadReferenceJsonWithWarnings(WriteText(dir, "p.json", R"({
    "lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": null, "plane_index": [0, 0, 1, 2],
               "color": "red"}],
    "planes": [{"inlier": [0, 0, 0], "normal": [1, 0, 0]}, {"inlier": [0, 0, 0], "normal": [0, 1, 0]},
               {"inlier": [0, 0, 0], "normal": [0, 0, 1]}]})"));
  ASSERT_TRUE(result) << result.error().ToString();
  const PlaneMembership& m = result->scene.memberships[SegmentId(0u)];
  EXPECT_EQ(m.count, 2);
  EXPECT_EQ(m.planes[1], PlaneId(1u));
  EXPECT_EQ(result->scene.observations[SegmentId(0u)].size(), 0u);
  ASSERT_EQ(result->warnings.size(), 3u);
  EXPECT_NE(result->warnings[0].find("repeat"), std::string::npos);
  EXPECT_NE(result->warnings[1].find("beyond the second"), std::string::npos);
  EXPECT_NE(result->warnings[2].find("color"), std::string::npos);
}

struct BadInput {
  const char* name;
  const char* text;
  const char* expected;  // substring of the error message
};

class ReferenceJsonBad : public ::testing::TestWithParam<BadInput> {};

TEST_P(ReferenceJsonBad, FailsWithInvalidInputNamingTheProblem) {
  const auto dir = testing::FreshTempDir();
  const auto path = WriteText(dir, std::string(GetParam().name) + ".json", GetParam().text);
  const auto scene = ReadReferenceJson(path);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(scene.error().message.find(GetParam().expected), std::string::npos)
      << scene.error().message;
  EXPECT_NE(scene.error().message.find(path.string()), std::string::npos)
      << scene.error().message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ReferenceJsonBad,
    ::testing::Values(
        BadInput{"empty", "", "empty file"},
        BadInput{"truncated", R"({"lines": [{"pt1": [0, 0)", "truncated JSON"},
        BadInput{"nan_text", R"({"lines": [{"pt1": [NaN, 0, 0]}]})", "no NaN"},
        BadInput{"huge", R"({"lines": [{"pt1": [0, 1e999, 0], "pt2": [0, 0, 0], "pt_views": []}]})",
                 "lines[0].pt1[1]: not a finite number"},
        BadInput{"missing_pt2", R"({"lines": [{"pt1": [0, 0, 0], "pt_views": []}]})",
                 "lines[0].pt2: missing"},
        BadInput{"views_flat",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [1, 2, 3]}]})",
                 "lines[0].pt_views: not a list of [x,y,z] triples"},
        BadInput{"views_pair",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [[1, 2]]}]})",
                 "lines[0].pt_views: not a list of [x,y,z] triples"},
        BadInput{"short_point", R"({"lines": [{"pt1": [0, 0], "pt2": [1, 0, 0], "pt_views": []}]})",
                 "lines[0].pt1: expected 3 coordinates"},
        BadInput{"string_coord",
                 R"({"lines": [{"pt1": [0, "a", 0], "pt2": [1, 0, 0], "pt_views": []}]})",
                 "lines[0].pt1[1]: not a number"},
        BadInput{"index_range",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [], "plane_index": [0, 3]}], "planes": [{"inlier": [0, 0, 0], "normal": [0, 0, 1]}]})",
                 "lines[0].plane_index[1]: 3 out of range (1 planes)"},
        BadInput{"index_negative",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [], "plane_index": [-1]}]})",
                 "lines[0].plane_index[0]: -1 out of range (0 planes)"},
        BadInput{"index_float",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [], "plane_index": [0.5]}]})",
                 "lines[0].plane_index[0]: not an integer"},
        BadInput{"zero_normal", R"({"planes": [{"inlier": [0, 0, 0], "normal": [0, 0, 1]},
                 {"inlier": [0, 0, 0], "normal": [0, 0, 0]}]})",
                 "planes[1].normal: zero length"},
        BadInput{"missing_normal", R"({"planes": [{"inlier": [0, 0, 0]}]})",
                 "planes[0].normal: missing"},
        BadInput{"not_object", "[1, 2]", "top level: expected a JSON object"},
        BadInput{"lines_object", R"({"lines": {"pt1": 1}})", "lines: not a list"},
        BadInput{"duplicate_key",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": []}]})",
                 "lines[0].pt1: duplicate key"},
        BadInput{"residual_count",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [[0, 0, 1]], "residual_per_pt_view": []}]})",
                 "1 pt_views"},
        BadInput{"trailing", R"({"lines": []} x)", "malformed JSON"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

TEST(ReferenceJson, MissingFileIsInvalidInput) {
  const auto dir = testing::FreshTempDir();
  const auto scene = ReadReferenceJson(dir / "nope.json");
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(scene.error().message.find("no such file"), std::string::npos);
}

TEST(ReferenceJson, WriterRejectsNonFiniteAndLeavesNoFile) {
  const auto dir = testing::FreshTempDir();
  Scene scene;
  scene.segments.push_back(Segment3{Vec3(0, 0, 0), Vec3(std::nan(""), 0, 0)});
  scene.observations.AddRow(std::vector<ViewpointId>{});
  const Status status = WriteReferenceJson(scene, dir / "bad.json");
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("lines[0].pt2"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.json.tmp"));
}

}  // namespace
}  // namespace linesurf::io
