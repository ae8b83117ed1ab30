// Runs `linesurf info` and `linesurf convert` as a user would and checks output and exit codes.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

namespace linesurf {
namespace {

using CliRun = testing::CliRunResult;
using testing::Slurp;
using testing::RunLinesurf;

std::string Quote(const std::string& s) { return testing::ShellQuote(s); }

std::filesystem::path WriteText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

class CliIo : public testing::CliTest {};

TEST_F(CliIo, InfoOnAndalusianPrintsTheReferenceCounts) {
  LINESURF_REQUIRE_ANDALUSIAN(input);
  const CliRun r = RunLinesurf("info " + Quote(input.string()), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("segments: 14503\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("planes: 148\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("viewpoints: 249\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("segments with 0 / 1 / 2 planes: 1046 / 6440 / 7017\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("views per segment:"), std::string::npos);
  EXPECT_NE(r.out.find("segment length histogram:"), std::string::npos);
  EXPECT_NE(r.out.find("plane points far from the data re-anchored"), std::string::npos) << r.out;
}

TEST_F(CliIo, InfoJsonIsMachineReadable) {
  const auto path = WriteText(dir_ / "s.json", R"({"lines": [
    {"pt1": [0, 0, 0], "pt2": [2, 0, 0], "pt_views": [[0, 5, 0], [1, 5, 0]], "plane_index": [0]},
    {"pt1": [0, 0, 1], "pt2": [0, 0, 2], "pt_views": [[0, 5, 0]], "plane_index": []}],
    "planes": [{"inlier": [0, 0, 0], "normal": [0, 1, 0]}]})");
  const CliRun r = RunLinesurf("info --json " + Quote(path.string()), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"segments\": 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"viewpoints\": 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"observations\": 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"segments_by_plane_count\""), std::string::npos) << r.out;
}

TEST_F(CliIo, ConvertLine3dppWithNvmKeepsEveryValue) {
  WriteText(dir_ / "m.nvm", "NVM_V3\n\n2\na.jpg 500 1 0 0 0 0.1 0.2 0.3 0 0\n"
                            "b.jpg 500 1 0 0 0 -4.5 6 7.25 0 0\n\n0\n");
  WriteText(dir_ / "l.txt", "1 0 0 0 1.0000000000000002 0 0 2 0 3 1.5 2.5 3.5 4.5 1 0 1 2 3 4\n");
  const CliRun r = RunLinesurf("convert " + Quote((dir_ / "l.txt").string()) + " --nvm " +
                                      Quote((dir_ / "m.nvm").string()) + " -o " +
                                      Quote((dir_ / "o.json").string()),
                                  dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = Slurp(dir_ / "o.json");
  EXPECT_NE(json.find("\"pt2\": [1.0000000000000002, 0.0, 0.0]"), std::string::npos) << json;
  EXPECT_NE(json.find("[[0.1, 0.2, 0.3], [-4.5, 6.0, 7.25]]"), std::string::npos) << json;
  EXPECT_NE(json.find("[[1.5, 2.5, 3.5, 4.5], [1.0, 2.0, 3.0, 4.0]]"), std::string::npos) << json;
  // Converting the JSON again gives the same bytes.
  const CliRun again = RunLinesurf(
      "convert " + Quote((dir_ / "o.json").string()) + " -o " + Quote((dir_ / "p.json").string()),
      dir_);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(json, Slurp(dir_ / "p.json"));
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Lines that say "on no plane" (empty plane_index lists) in a file without planes: convert
// keeps the lists (the reference's reconstruction requires the key on every line) and the
// empty plane list, with and without --sanitize, and converting the output again gives the same
// bytes (the empty lists are kept, not dropped).
TEST_F(CliIo, ConvertKeepsEmptyPlaneIndexListsWithoutPlanes) {
  const auto path = WriteText(dir_ / "unassigned.json", R"({"lines": [
    {"pt1": [0, 0, 0], "pt2": [2, 0, 0], "pt_views": [[0, 5, 0]], "plane_index": []},
    {"pt1": [0, 0, 1], "pt2": [0, 0, 3], "pt_views": [[0, 5, 0]]}]})");
  for (const std::string flags : {"", "--sanitize "}) {
    const CliRun r = RunLinesurf(
        "convert " + flags + Quote(path.string()) + " -o " + Quote((dir_ / "o.json").string()),
        dir_);
    ASSERT_EQ(r.exit_code, 0) << flags << r.err;
    const std::string json = Slurp(dir_ / "o.json");
    EXPECT_EQ(Count(json, "\"plane_index\": []"), 2u) << flags << json;
    EXPECT_EQ(Count(json, "\"planes\": []"), 1u) << flags << json;
    const CliRun again = RunLinesurf(
        "convert " + Quote((dir_ / "o.json").string()) + " -o " + Quote((dir_ / "p.json").string()),
        dir_);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(json, Slurp(dir_ / "p.json")) << flags;
  }
  // A file without plane_index keys or planes stays without them.
  const auto bare = WriteText(
      dir_ / "bare.json", R"({"lines": [{"pt1": [0, 0, 0], "pt2": [2, 0, 0], "pt_views": []}]})");
  const CliRun r = RunLinesurf(
      "convert " + Quote(bare.string()) + " -o " + Quote((dir_ / "b.json").string()), dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = Slurp(dir_ / "b.json");
  EXPECT_EQ(json.find("plane"), std::string::npos) << json;
}

TEST_F(CliIo, DetectWritesPlanesVertexGroupsAndAReport) {
  const CliRun synth =
      RunLinesurf("-q synth cube --seed 1 -o " + Quote((dir_ / "cube").string()), dir_);
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  const CliRun r = RunLinesurf(
      "detect " + Quote((dir_ / "cube" / "lines.json").string()) + " --epsilon 0.06 -o " +
          Quote((dir_ / "planes.json").string()) + " --vg " + Quote((dir_ / "planes.vg").string()) +
          " --report " + Quote((dir_ / "report.json").string()),
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("6 planes"), std::string::npos) << r.err;
  // The clean cube: 6 faces, each holding its 4 edges of length 2.
  const std::string report = Slurp(dir_ / "report.json");
  EXPECT_EQ(Count(report, "\"inlier_count\": 4,"), 6u) << report;
  EXPECT_EQ(Count(report, "\"inlier_length\": 8.0"), 6u) << report;
  EXPECT_NE(report.find("\"segments_with_2_planes\": 12"), std::string::npos) << report;
  EXPECT_NE(report.find("\"epsilon\": 0.06"), std::string::npos) << report;
  EXPECT_EQ(Count(Slurp(dir_ / "planes.json"), "\"normal\""), 6u);
  EXPECT_NE(Slurp(dir_ / "planes.vg").find("num_groups: 6"), std::string::npos);
  // An unwritable report is an error naming the file.
  const CliRun bad = RunLinesurf(
      "detect " + Quote((dir_ / "cube" / "lines.json").string()) + " -o " +
          Quote((dir_ / "p2.json").string()) + " --report " +
          Quote((dir_ / "missing" / "report.json").string()),
      dir_);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("missing/report.json"), std::string::npos) << bad.err;
}

TEST_F(CliIo, ConfigFileSetsOptionsAndTheReportHoldsTheEffectiveOnes) {
  const CliRun synth =
      RunLinesurf("-q synth cube --seed 1 -o " + Quote((dir_ / "cube").string()), dir_);
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  // Keys are the options' paths, nested or dotted.
  WriteText(dir_ / "config.json",
            R"({"detection": {"epsilon": 0.06}, "detection.max_planes": 5, "seed": 9})");
  const std::string input = Quote((dir_ / "cube" / "lines.json").string());
  const std::string config = " --config " + Quote((dir_ / "config.json").string());
  CliRun r = RunLinesurf("detect " + input + config + " --max-planes 4 -o " +
                             Quote((dir_ / "p.json").string()) + " --report " +
                             Quote((dir_ / "r.json").string()),
                         dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json report = nlohmann::json::parse(Slurp(dir_ / "r.json"));
  EXPECT_EQ(report["options"]["detection"]["epsilon"], 0.06) << report;  // from the file
  EXPECT_EQ(report["options"]["detection"]["max_planes"], 4) << report;  // flag wins
  EXPECT_EQ(report["options"]["seed"], 9) << report;
  EXPECT_EQ(report["options"]["detection"]["block_halo"], 0.1) << report;  // a default
  EXPECT_NE(r.err.find("4 planes"), std::string::npos) << r.err;
  // reconstruct: the same options, its own, and the detection ones in one report.
  WriteText(dir_ / "rconfig.json",
            R"({"detection.epsilon": 0.06, "scene_mode": "exterior", "weights": {"edge": 0.5}})");
  r = RunLinesurf("reconstruct " + input + " --config " +
                      Quote((dir_ / "rconfig.json").string()) + " -o " +
                      Quote((dir_ / "m.ply").string()) + " --report " +
                      Quote((dir_ / "rr.json").string()),
                  dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  report = nlohmann::json::parse(Slurp(dir_ / "rr.json"));
  EXPECT_EQ(report["options"]["scene_mode"], "exterior") << report;
  EXPECT_EQ(report["options"]["weights"]["edge"], 0.5) << report;
  EXPECT_EQ(report["options"]["detection"]["epsilon"], 0.06) << report;
  EXPECT_EQ(report["options"]["plane_source"], "detect") << report;
  EXPECT_EQ(report["output_options"]["ascii"], false) << report;
  // A key no option has is a usage error naming it; a missing file is invalid input.
  WriteText(dir_ / "bad.json", R"({"detection.epsilon": 0.06, "weights": {"edges": 0.5}})");
  r = RunLinesurf("reconstruct " + input + " --config " + Quote((dir_ / "bad.json").string()) +
                      " -o " + Quote((dir_ / "m2.ply").string()),
                  dir_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.json: 'weights.edges' is not an option of this command"),
            std::string::npos)
      << r.err;
  r = RunLinesurf("detect " + input + " --config nothing.json -o " +
                      Quote((dir_ / "p3.json").string()),
                  dir_);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("nothing.json: no such file"), std::string::npos) << r.err;
}

TEST_F(CliIo, UsageErrorsExitWithTwo) {
  WriteText(dir_ / "l.txt", "1 0 0 0 1 0 0 0\n");
  CliRun r = RunLinesurf("info " + Quote((dir_ / "l.txt").string()), dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--nvm"), std::string::npos) << r.err;
  r = RunLinesurf("convert " + Quote((dir_ / "l.txt").string()) + " -o x.ply", dir_);
  EXPECT_EQ(r.exit_code, 2);
  r = RunLinesurf("info", dir_);
  EXPECT_EQ(r.exit_code, 2);
}

struct BadInput {
  const char* name;
  const char* text;  // nullptr: the file does not exist
  const char* expected;
};

class CliIoBad : public CliIo, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliIoBad, InfoAndConvertExitWithThreeNamingTheProblem) {
  const auto path = dir_ / (std::string(GetParam().name) + ".json");
  if (GetParam().text != nullptr) WriteText(path, GetParam().text);
  for (const std::string cmd : {"info ", "convert -o out.json "}) {
    const CliRun r = RunLinesurf(cmd + Quote(path.string()), dir_);
    EXPECT_EQ(r.exit_code, 3) << cmd << r.err;
    EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << cmd << r.err;
    EXPECT_NE(r.err.find(path.filename().string()), std::string::npos) << r.err;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliIoBad,
    ::testing::Values(
        BadInput{"empty", "", "empty file"}, BadInput{"missing", nullptr, "no such file"},
        BadInput{"truncated", R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1,)", "truncated JSON"},
        BadInput{"nan_literal", R"({"lines": [{"pt1": [NaN, 0, 0], "pt2": [1, 0, 0], "pt_views": []}]})",
                 "JSON has no NaN or Infinity literal"},
        BadInput{"overflow", R"({"lines": [{"pt1": [0, 0, 1e999], "pt2": [1, 0, 0], "pt_views": []}]})",
                 "lines[0].pt1[2]: not a finite number"},
        BadInput{"missing_pt2", R"({"lines": [{"pt1": [0, 0, 0], "pt_views": []}]})",
                 "lines[0].pt2: missing"},
        BadInput{"views_not_triples",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [[1, 2, 3], [4, 5]]}]})",
                 "lines[0].pt_views: not a list of [x,y,z] triples"},
        BadInput{"index_range",
                 R"({"lines": [{"pt1": [0, 0, 0], "pt2": [1, 0, 0], "pt_views": [], "plane_index": [200]}],
                    "planes": [{"inlier": [0, 0, 0], "normal": [0, 0, 1]}]})",
                 "lines[0].plane_index[0]: 200 out of range (1 planes)"},
        BadInput{"zero_normal",
                 R"({"lines": [], "planes": [{"inlier": [0, 0, 0], "normal": [0, 0, 0]}]})",
                 "planes[0].normal: zero length"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

TEST_F(CliIo, AbsurdCoordinatesGiveAClearErrorNotACrash) {
  const auto path = WriteText(dir_ / "huge.json", R"({"lines": [
    {"pt1": [1e300, 0, 0], "pt2": [-1e300, 1e300, 0], "pt_views": [[1e308, 0, 0]]}]})");
  const CliRun info = RunLinesurf("info " + Quote(path.string()), dir_);
  EXPECT_EQ(info.exit_code, 3) << info.err;
  EXPECT_NE(info.err.find("no usable segment left"), std::string::npos) << info.err;
  EXPECT_NE(info.err.find("beyond +-1.00e+12"), std::string::npos) << info.err;
  // Converting keeps the values as they are (no sanitation unless asked).
  const CliRun convert =
      RunLinesurf("convert " + Quote(path.string()) + " -o " + Quote((dir_ / "o.json").string()), dir_);
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  const CliRun sanitized = RunLinesurf("convert --sanitize " + Quote(path.string()) + " -o " +
                                              Quote((dir_ / "s.json").string()),
                                          dir_);
  EXPECT_EQ(sanitized.exit_code, 3) << sanitized.err;
}

}  // namespace
}  // namespace linesurf
