// Every scene input format with its camera model through `linesurf reconstruct` and `detect`:
// the synthetic house's lines written by the test as Line3D++ with an
// NVM model, with a COLMAP text and a COLMAP binary model, and as LIMAP alltracks.txt with its
// COLMAP model give the same mesh bytes and the same planes as the reference JSON; bad and
// missing camera ids exit with 3 naming the file and line.

#include "engine/io/reference_json.h"
#include "tests/support/cli_runner.h"
#include "tests/support/sfm_fixtures.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace linesurf {
namespace {

using testing::CliRunResult;
using testing::Slurp;
using testing::WriteFixture;

std::string Quote(const std::filesystem::path& p) { return testing::ShellQuote(p.string()); }

/// One way of giving the house: the scene file and its camera options.
struct Variant {
  std::string name;
  std::filesystem::path input;
  std::string camera_options;
};

class CliInputs : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    const CliRunResult synth = testing::RunLinesurf(
        "-q synth house --seed 3 --noise 0.002 -o " + Quote(dir_ / "house"), dir_);
    ASSERT_EQ(synth.exit_code, 0) << synth.err;
    auto scene = io::ReadReferenceJson(dir_ / "house" / "lines.json");
    ASSERT_TRUE(scene) << scene.error().ToString();
    scene_ = std::move(*scene);
    ASSERT_GT(scene_.viewpoints.size(), 3u);

    const auto nvm_cameras = testing::CamerasFor(scene_, 0, 1);
    const auto colmap_cameras = testing::CamerasFor(scene_, 11, 7);  // sparse IMAGE_IDs
    WriteFixture(dir_ / "model.nvm", testing::NvmText(nvm_cameras));
    WriteFixture(dir_ / "lines_nvm.txt", testing::Line3dppText(scene_, nvm_cameras));
    WriteFixture(dir_ / "lines_colmap.txt", testing::Line3dppText(scene_, colmap_cameras));
    std::filesystem::create_directories(dir_ / "sparse_txt");
    std::filesystem::create_directories(dir_ / "sparse_bin");
    WriteFixture(dir_ / "sparse_txt" / "images.txt", testing::ColmapImagesText(colmap_cameras));
    WriteFixture(dir_ / "sparse_txt" / "cameras.txt", testing::ColmapCamerasText());
    WriteFixture(dir_ / "sparse_bin" / "images.bin", testing::ColmapImagesBinary(colmap_cameras));
    WriteFixture(dir_ / "sparse_bin" / "cameras.bin", testing::ColmapCamerasBinary());
    WriteFixture(dir_ / "alltracks.txt", testing::LimapText(scene_, colmap_cameras));
  }

  [[nodiscard]] std::vector<Variant> Variants() const {
    return {
        {"line3dpp_nvm", dir_ / "lines_nvm.txt", " --nvm " + Quote(dir_ / "model.nvm")},
        {"line3dpp_colmap_text",
         dir_ / "lines_colmap.txt",
         " --colmap " + Quote(dir_ / "sparse_txt")},
        {"line3dpp_colmap_binary",
         dir_ / "lines_colmap.txt",
         " --colmap " + Quote(dir_ / "sparse_bin")},
        {"limap_colmap_binary", dir_ / "alltracks.txt", " --colmap " + Quote(dir_ / "sparse_bin")},
        {"limap_colmap_text",
         dir_ / "alltracks.txt",
         " --colmap " + Quote(dir_ / "sparse_txt" / "images.txt")}};
  }

  CliRunResult Run(const std::string& args) { return testing::RunLinesurf("-q " + args, dir_); }

  Scene scene_;
};

TEST_F(CliInputs, ReconstructGivesTheSameMeshFromEveryFormat) {
  const CliRunResult ref =
      Run("reconstruct " + Quote(dir_ / "house" / "lines.json") + " -o " + Quote(dir_ / "ref.ply"));
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const std::string expected = Slurp(dir_ / "ref.ply");
  ASSERT_FALSE(expected.empty());
  for (const Variant& v : Variants()) {
    const auto out = dir_ / (v.name + ".ply");
    const CliRunResult r =
        Run("reconstruct " + Quote(v.input) + v.camera_options + " -o " + Quote(out));
    ASSERT_EQ(r.exit_code, 0) << v.name << ": " << r.err;
    EXPECT_EQ(Slurp(out), expected) << v.name;
  }
}

/// The detected planes of a `detect` output file and the per-plane support of its report.
nlohmann::json DetectedPlanes(const std::filesystem::path& output,
                              const std::filesystem::path& report) {
  return {nlohmann::json::parse(Slurp(output))["planes"],
          nlohmann::json::parse(Slurp(report))["planes"]};
}

TEST_F(CliInputs, DetectGivesTheSamePlanesFromEveryFormat) {
  const CliRunResult ref =
      Run("detect " + Quote(dir_ / "house" / "lines.json") + " -o " + Quote(dir_ / "ref.json") +
          " --report " + Quote(dir_ / "ref_report.json"));
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const nlohmann::json expected = DetectedPlanes(dir_ / "ref.json", dir_ / "ref_report.json");
  ASSERT_GE(expected[0].size(), 4u);
  for (const Variant& v : Variants()) {
    const auto out = dir_ / (v.name + ".json");
    const auto report = dir_ / (v.name + "_report.json");
    const CliRunResult r = Run("detect " + Quote(v.input) + v.camera_options + " -o " + Quote(out) +
                               " --report " + Quote(report));
    ASSERT_EQ(r.exit_code, 0) << v.name << ": " << r.err;
    EXPECT_EQ(DetectedPlanes(out, report), expected) << v.name;
  }
}

/// `text` with token `index` (0-based) of 1-based line `line` replaced by `token`.
std::string ReplaceToken(const std::string& text,
                         int line,
                         std::size_t index,
                         const std::string& token) {
  std::size_t start = 0;
  for (int l = 1; l < line; ++l) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  std::istringstream in(text.substr(start, end - start));
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  EXPECT_GT(tokens.size(), index) << "line " << line;
  tokens[index] = token;
  std::string joined;
  for (const std::string& t : tokens) joined += (joined.empty() ? "" : " ") + t;
  return text.substr(0, start) + joined + text.substr(end);
}

TEST_F(CliInputs, BadAndMissingCameraIdsExitWithThreeNamingTheLine) {
  // Line3D++ line 3: token 8 is its first observation's camera id (after the segment count,
  // 6 coordinates and the observation count). LIMAP: track 1's image ids are line 2 + 5 + 3.
  const std::string l3d = Slurp(dir_ / "lines_nvm.txt");
  const std::string limap = Slurp(dir_ / "alltracks.txt");
  const std::string nvm = " --nvm " + Quote(dir_ / "model.nvm");
  struct Case {
    std::string file;
    std::string text;
    std::string options;
    std::string expected;
  };
  const std::string colmap = " --colmap " + Quote(dir_ / "sparse_bin");
  const Case cases[] = {
      {"missing_cam.txt",
       ReplaceToken(l3d, 3, 8, "999"),
       nvm,
       "missing_cam.txt: line 3: observation 0: camera id 999 is not in the camera model (" +
           std::to_string(scene_.viewpoints.size()) + " cameras)"},
      {"bad_cam.txt",
       ReplaceToken(l3d, 3, 8, "7x"),
       nvm,
       "bad_cam.txt: line 3: observation 0: camera id '7x' is not an integer"},
      {"missing_image.txt",
       ReplaceToken(limap, 10, 0, "12"),
       colmap,  // not an IMAGE_ID
       "missing_image.txt: line 10: track 1: image id 12 is not in the camera model"},
      {"bad_image.txt",
       ReplaceToken(limap, 10, 0, "eleven"),
       colmap,
       "bad_image.txt: line 10: track 1: image id 'eleven' is not an integer"},
  };
  for (const Case& c : cases) {
    WriteFixture(dir_ / c.file, c.text);
    for (const auto& [command, output] :
         {std::pair<std::string, std::string>{"reconstruct", ".ply"}, {"detect", ".json"}}) {
      const CliRunResult r = Run(command + " " + Quote(dir_ / c.file) + c.options + " -o " +
                                 Quote(dir_ / (c.file + output)));
      EXPECT_EQ(r.exit_code, 3) << command << " " << c.file << ": " << r.err;
      EXPECT_NE(r.err.find(c.expected), std::string::npos) << command << ": " << r.err;
    }
  }
  // No camera model at all is a usage error naming the options.
  const CliRunResult r = Run("reconstruct " + Quote(dir_ / "alltracks.txt") + " -o m.ply");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--colmap"), std::string::npos) << r.err;
}

TEST_F(CliInputs, RenderAndInfoReadEveryFormatToo) {
  const CliRunResult info = Run("info --json " + Quote(dir_ / "alltracks.txt") + " --colmap " +
                                Quote(dir_ / "sparse_bin"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["segments"], scene_.NumSegments());
  const CliRunResult render =
      Run("render --lines " + Quote(dir_ / "lines_nvm.txt") + " --nvm " +
          Quote(dir_ / "model.nvm") + " --size 64x48 -o " + Quote(dir_ / "l.png"));
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_FALSE(Slurp(dir_ / "l.png").empty());
}

TEST_F(CliInputs, ReconstructWritesCityJson) {
  const CliRunResult r = Run("reconstruct " + Quote(dir_ / "house" / "lines.json") + " -o " +
                             Quote(dir_ / "house.city.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json city = nlohmann::json::parse(Slurp(dir_ / "house.city.json"));
  EXPECT_EQ(city["version"], "2.0");
  ASSERT_EQ(city["CityObjects"].size(), 1u);  // the house is one connected part
  const auto& geometry = city["CityObjects"]["building_0"]["geometry"][0];
  EXPECT_EQ(geometry["type"], "Solid");
  std::size_t on_planes = 0;
  std::set<std::string> types;
  for (const auto& s : geometry["semantics"]["surfaces"]) {
    types.insert(s["type"].get<std::string>());
    on_planes += s.contains("plane_index");
  }
  EXPECT_EQ(types, (std::set<std::string>{"GroundSurface", "RoofSurface", "WallSurface"}));
  EXPECT_EQ(on_planes, geometry["semantics"]["surfaces"].size());  // every face on a plane
  // --cityjson forces the format whatever the extension.
  const CliRunResult forced = Run("reconstruct " + Quote(dir_ / "house" / "lines.json") +
                                  " --cityjson -o " + Quote(dir_ / "house.json"));
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(Slurp(dir_ / "house.json"), Slurp(dir_ / "house.city.json"));
  // A .city.jsonl name writes CityJSONSeq: a header line and one feature line per building.
  const CliRunResult sequence = Run("reconstruct " + Quote(dir_ / "house" / "lines.json") +
                                    " -o " + Quote(dir_ / "house.city.jsonl"));
  ASSERT_EQ(sequence.exit_code, 0) << sequence.err;
  std::istringstream lines(Slurp(dir_ / "house.city.jsonl"));
  std::vector<nlohmann::json> parsed;
  for (std::string line; std::getline(lines, line);) parsed.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(parsed.size(), 2u);
  EXPECT_EQ(parsed[0]["type"], "CityJSON");
  EXPECT_EQ(parsed[1]["type"], "CityJSONFeature");
  EXPECT_EQ(parsed[1]["CityObjects"]["building_0"], city["CityObjects"]["building_0"]);
}

/// Per semantic class, the number of surfaces of the first building.
std::map<std::string, int> SurfaceClasses(const nlohmann::json& city) {
  std::map<std::string, int> count;
  for (const auto& s : city["CityObjects"]["building_0"]["geometry"][0]["semantics"]["surfaces"]) {
    ++count[s["type"].get<std::string>()];
  }
  return count;
}

// A house and a room turned so that their up is not z: roofs, walls and ground (floors and
// ceilings inside) by the data's up, which the report names.
TEST_F(CliInputs, CityJsonClassifiesByTheDatasUp) {
  const auto json = [&](const std::string& file) {
    return nlohmann::json::parse(Slurp(dir_ / file));
  };
  for (const std::string family : {"house", "room"}) {
    SCOPED_TRACE(family);
    std::map<std::string, int> given;
    for (const std::string turn : {"", " --rotate 1,2,3,70"}) {
      const std::string name = family + (turn.empty() ? "_given" : "_turned");
      const CliRunResult synth =
          Run("synth " + family + " --seed 3 --noise 0.002" + turn + " -o " + Quote(dir_ / name));
      ASSERT_EQ(synth.exit_code, 0) << synth.err;
      const CliRunResult r = Run("reconstruct " + Quote(dir_ / name / "lines.json") + " -o " +
                                 Quote(dir_ / (name + ".city.json")) + " --report " +
                                 Quote(dir_ / (name + ".report.json")));
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const std::map<std::string, int> classes = SurfaceClasses(json(name + ".city.json"));
      EXPECT_EQ(classes.size(), 3u);
      if (turn.empty()) given = classes;
      EXPECT_EQ(classes, given);
      const nlohmann::json up = json(name + "/meta.json")["up"];
      const nlohmann::json frame = json(name + ".report.json")["frame"];
      EXPECT_TRUE(frame["aligned"].get<bool>());
      EXPECT_EQ(frame["up_evidence"], "viewpoint_spread");
      double dot = 0.0;
      for (int k = 0; k < 3; ++k) dot += frame["up"][k].get<double>() * up[k].get<double>();
      EXPECT_GT(dot, 0.9999);
    }
  }
}

}  // namespace
}  // namespace linesurf
