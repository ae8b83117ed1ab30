// Hostile inputs through the installed facade (linesurf/linesurf.h, the shared library): every
// call returns an Error with the expected code and a message naming the place (the field, the
// array entry, the file), never aborts, never prints, and a failed write leaves no file.

#include "linesurf/linesurf.h"

#include "tests/robustness/hostile_case.h"
#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace linesurf::robustness {
namespace {
namespace fs = std::filesystem;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The 12 edges of the cube [-1, 1]^3, each seen from the 8 viewpoints at (+-4, +-4, +-4).
SceneData CubeData() {
  SceneData scene;
  for (int v = 0; v < 8; ++v) {
    scene.viewpoints.push_back({v & 1 ? 4.0 : -4.0, v & 2 ? 4.0 : -4.0, v & 4 ? 4.0 : -4.0});
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int corner = 0; corner < 4; ++corner) {
      Segment s;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      s.p1[axis] = -1.0;
      s.p2[axis] = 1.0;
      s.p1[u] = s.p2[u] = corner & 1 ? 1.0 : -1.0;
      s.p1[w] = s.p2[w] = corner & 2 ? 1.0 : -1.0;
      const auto segment = static_cast<std::uint32_t>(scene.segments.size());
      scene.segments.push_back(s);
      for (std::uint32_t v = 0; v < 8; ++v) scene.observations.push_back({segment, v});
    }
  }
  return scene;
}

ReconstructOptions ExteriorOptions() {
  ReconstructOptions o;
  o.scene_mode = SceneMode::kExterior;
  return o;
}

/// What a case's calls returned: the first error (none: success).
struct Outcome {
  bool ok = true;
  Error error;
};

template <typename T>
Outcome OutcomeOf(const Expected<T>& result) {
  if (result.has_value()) return {};
  return {false, result.error()};
}

struct FacadeCase {
  std::string name;
  /// Runs the calls in `dir` (an empty scratch directory) and returns what they gave.
  std::function<Outcome(const fs::path& dir)> run;
  ErrorCode expected;
  /// Strings the message ("stage: message") must contain; {dir} stands for the scratch dir.
  std::vector<std::string> message;
};

void PrintTo(const FacadeCase& c, std::ostream* os) { *os << c.name; }

/// A reconstruction of the cube with `spoil` applied to the scene.
FacadeCase SceneCase(std::string name,
                     std::function<void(SceneData&)> spoil,
                     ErrorCode expected,
                     std::vector<std::string> message,
                     PlaneSource planes = PlaneSource::kDetect) {
  auto run = [spoil, planes](const fs::path&) {
    SceneData scene = CubeData();
    spoil(scene);
    ReconstructOptions o = ExteriorOptions();
    o.plane_source = planes;
    return OutcomeOf(Reconstruct(scene.View(), o));
  };
  return {std::move(name), run, expected, std::move(message)};
}

/// A reconstruction of the cube with `spoil` applied to the options: Validate() and
/// Reconstruct() both refuse them, naming the field.
FacadeCase OptionCase(std::string name,
                      std::function<void(ReconstructOptions&)> spoil,
                      std::string field) {
  auto run = [spoil](const fs::path&) {
    ReconstructOptions o = ExteriorOptions();
    spoil(o);
    const Status validated = o.Validate();
    if (validated) return Outcome{};
    const SceneData scene = CubeData();
    const auto result = Reconstruct(scene.View(), o);
    if (result) return Outcome{};
    // Both must name the same field; report the call's error.
    return OutcomeOf(result);
  };
  return {std::move(name), run, ErrorCode::kInvalidOptions, {std::move(field)}};
}

FacadeCase DetectOptionCase(std::string name,
                            std::function<void(DetectOptions&)> spoil,
                            std::string field) {
  auto run = [spoil](const fs::path&) {
    DetectOptions o;
    spoil(o);
    if (o.Validate()) return Outcome{};
    const SceneData scene = CubeData();
    return OutcomeOf(DetectPlanes(scene.View(), o));
  };
  return {std::move(name), run, ErrorCode::kInvalidOptions, {std::move(field)}};
}

/// A run whose control asks to stop: by the cancel callback (at once or after `polls` polls) or
/// by a throwing progress callback.
FacadeCase CancelCase(std::string name, std::function<RunControl()> control) {
  auto run = [control](const fs::path&) {
    const SceneData scene = CubeData();
    return OutcomeOf(Reconstruct(scene.View(), ExteriorOptions(), control()));
  };
  return {std::move(name), run, ErrorCode::kCancelled, {}};
}

Mesh Triangle() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.face_offsets = {0, 3};
  mesh.face_indices = {0, 1, 2};
  return mesh;
}

std::vector<FacadeCase> FacadeCases() {
  std::vector<FacadeCase> cases;
  const auto add = [&cases](FacadeCase c) { cases.push_back(std::move(c)); };
  using E = ErrorCode;

  // Scenes: empty views, non-finite and out-of-bound coordinates, indices out of range.
  add({"empty_views",
       [](const fs::path&) { return OutcomeOf(Reconstruct(InputScene{}, ExteriorOptions())); },
       E::kInvalidInput,
       {"segment"}});
  add({"detect_empty_views",
       [](const fs::path&) { return OutcomeOf(DetectPlanes(InputScene{}, DetectOptions{})); },
       E::kInvalidInput,
       {"segment"}});
  add(SceneCase("every_segment_nan",
                [](SceneData& s) {
                  for (Segment& g : s.segments) g.p1[0] = kNan;
                },
                E::kInvalidInput,
                {"segment", "non-finite"}));
  add(SceneCase("every_segment_inf",
                [](SceneData& s) {
                  for (Segment& g : s.segments) g.p2[2] = -kInf;
                },
                E::kInvalidInput,
                {"segment", "non-finite"}));
  add(SceneCase("every_segment_beyond_bound",
                [](SceneData& s) {
                  for (Segment& g : s.segments) g.p1[1] = 1e15;
                },
                E::kInvalidInput,
                {"segment", "beyond"}));
  add(SceneCase(
      "every_viewpoint_nan",
      [](SceneData& s) {
        for (Vector3& v : s.viewpoints) v[0] = kNan;
      },
      E::kDegenerate,
      {"the surface is empty", "no viewpoint observes a segment", "8 viewpoints dropped"}));
  add(SceneCase("observation_segment_out_of_range",
                [](SceneData& s) {
                  s.observations.push_back({12, 0});
                },
                E::kInvalidInput,
                {"observations[96].segment = 12"}));
  add(SceneCase("observation_viewpoint_out_of_range",
                [](SceneData& s) { s.observations[5].viewpoint = 4000000000u; },
                E::kInvalidInput,
                {"observations[5].viewpoint = 4000000000"}));
  add(SceneCase(
      "membership_plane_out_of_range",
      [](SceneData& s) {
        s.planes = {Plane{{0, 0, 1}, {0, 0, 1}}};
        s.memberships = {{0, 0}, {1, 7}};
      },
      E::kInvalidInput,
      {"memberships[1].plane = 7"},
      PlaneSource::kGiven));
  add(SceneCase(
      "membership_without_planes",
      [](SceneData& s) {
        s.memberships = {{0, 0}};
      },
      E::kInvalidInput,
      {"memberships"},
      PlaneSource::kGiven));
  add(SceneCase(
      "segment_on_three_planes",
      [](SceneData& s) {
        s.planes = {
            Plane{{0, 0, 1}, {0, 0, 1}}, Plane{{0, 1, 0}, {0, 1, 0}}, Plane{{1, 0, 0}, {1, 0, 0}}};
        s.memberships = {{0, 0}, {0, 1}, {0, 2}};
      },
      E::kInvalidInput,
      {"memberships[2]", "two planes"},
      PlaneSource::kGiven));
  add(SceneCase(
      "given_planes_all_nan",
      [](SceneData& s) {
        s.planes = {Plane{{0, 0, 1}, {kNan, 0, 1}}, Plane{{0, 0, -1}, {0, kInf, 1}}};
        s.memberships = {{0, 0}, {1, 1}};
      },
      E::kDegenerate,
      {"no plane"},
      PlaneSource::kGiven));
  add({"sanitize_observation_out_of_range",
       [](const fs::path&) {
         SceneData scene = CubeData();
         scene.observations.push_back({0, 8});
         return OutcomeOf(SanitizeScene(scene));
       },
       E::kInvalidInput,
       {"observations[96].viewpoint = 8"}});

  // Options: Validate() names the first offending field; the calls refuse them too.
  add(OptionCase(
      "epsilon_nan", [](ReconstructOptions& o) { o.detection.epsilon = kNan; }, "epsilon"));
  add(OptionCase(
      "relative_epsilon_inf",
      [](ReconstructOptions& o) { o.detection.relative_epsilon = kInf; },
      "relative_epsilon"));
  add(OptionCase(
      "max_planes_negative",
      [](ReconstructOptions& o) { o.detection.max_planes = -5; },
      "max_planes"));
  add(OptionCase(
      "iterations_zero", [](ReconstructOptions& o) { o.detection.iterations = 0; }, "iterations"));
  add(OptionCase(
      "block_halo_half",
      [](ReconstructOptions& o) { o.detection.block_halo = 0.5; },
      "block_halo"));
  add(OptionCase(
      "weight_textural_negative",
      [](ReconstructOptions& o) { o.weights.textural = -1.0; },
      "weights.textural"));
  // One rule with the CLI (--w-edge 1e308 and -j 1000000 are refused there too).
  add(OptionCase(
      "weight_edge_1e308", [](ReconstructOptions& o) { o.weights.edge = 1e308; }, "weights.edge"));
  add(OptionCase(
      "num_threads_1000000",
      [](ReconstructOptions& o) { o.num_threads = 1000000; },
      "num_threads must be in [0, 256]"));
  add(OptionCase(
      "sigma_negative", [](ReconstructOptions& o) { o.sigma = -1.0; }, "sigma"));
  add(OptionCase(
      "sigma_nan", [](ReconstructOptions& o) { o.sigma = kNan; }, "sigma"));
  add(OptionCase(
      "samples_per_sigma_1e9",
      [](ReconstructOptions& o) { o.samples_per_sigma = 1e9; },
      "samples_per_sigma"));
  add(OptionCase(
      "box_margin_inf", [](ReconstructOptions& o) { o.box_margin = kInf; }, "box_margin"));
  add(OptionCase(
      "time_limit_nan",
      [](ReconstructOptions& o) { o.solver.time_limit_seconds = kNan; },
      "solver.time_limit_seconds"));
  add(OptionCase(
      "backend_out_of_enum",
      [](ReconstructOptions& o) { o.solver.backend = static_cast<SolverBackend>(99); },
      "solver.backend"));
  add(OptionCase(
      "scene_mode_out_of_enum",
      [](ReconstructOptions& o) { o.scene_mode = static_cast<SceneMode>(-1); },
      "scene_mode"));
  add(OptionCase(
      "planes_out_of_enum",
      [](ReconstructOptions& o) { o.plane_source = static_cast<PlaneSource>(5); },
      "plane_source"));
  add(DetectOptionCase(
      "detect_epsilon_zero", [](DetectOptions& o) { o.detection.epsilon = 0.0; }, "epsilon"));
  add(DetectOptionCase(
      "detect_num_threads_negative", [](DetectOptions& o) { o.num_threads = -1; }, "num_threads"));
  add(DetectOptionCase(
      "detect_num_threads_1000000",
      [](DetectOptions& o) { o.num_threads = 1000000; },
      "num_threads must be in [0, 256]"));
  add({"solve_weight_nan",
       [](const fs::path&) {
         const SceneData scene = CubeData();
         auto prepared = Reconstruction::Prepare(scene.View(), ExteriorOptions());
         if (!prepared) return OutcomeOf(prepared);
         EnergyWeights w;
         w.visibility = kNan;
         return OutcomeOf(prepared->Solve(w));
       },
       E::kInvalidOptions,
       {"weights.visibility"}});

  // Cancellation: at once, after some polls, by a throwing callback.
  add(CancelCase("cancel_at_once", [] {
    RunControl c;
    c.is_cancelled = [] { return true; };
    return c;
  }));
  add(CancelCase("cancel_mid_run", [] {
    RunControl c;
    auto polls = std::make_shared<std::atomic<int>>(0);
    c.is_cancelled = [polls] { return ++*polls > 3; };
    return c;
  }));
  add(CancelCase("progress_callback_throws", [] {
    RunControl c;
    c.on_progress = [](const Progress&) { throw std::runtime_error("host gave up"); };
    return c;
  }));

  // Files: a failed read names the file; a failed write leaves no file (checked by the test).
  add({"read_missing_file",
       [](const fs::path& dir) { return OutcomeOf(ReadScene((dir / "none.json").string())); },
       E::kInvalidInput,
       {"{dir}/none.json"}});
  add({"read_malformed_json",
       [](const fs::path& dir) {
         WriteFile(dir / "bad.json", "{\"lines\": [{\"pt1\": [0, 0], \"pt2\": [1, 0, 0]}]}");
         return OutcomeOf(ReadScene((dir / "bad.json").string()));
       },
       E::kInvalidInput,
       {"{dir}/bad.json", "lines[0].pt1"}});
  add({"read_unknown_format",
       [](const fs::path& dir) {
         WriteFile(dir / "lines.xyz", "0 0 0\n");
         return OutcomeOf(ReadScene((dir / "lines.xyz").string()));
       },
       E::kInvalidOptions,
       {"{dir}/lines.xyz"}});
  add({"write_mesh_into_missing_dir",
       [](const fs::path& dir) {
         return OutcomeOf(WriteMesh((dir / "no" / "m.ply").string(), Triangle()));
       },
       E::kInvalidInput,
       {"{dir}/no/m.ply"}});
  add({"write_mesh_unknown_extension",
       [](const fs::path& dir) {
         return OutcomeOf(WriteMesh((dir / "m.stl").string(), Triangle()));
       },
       E::kInvalidInput,
       {"{dir}/m.stl", ".stl"}});
  add({"write_mesh_nan_vertex",
       [](const fs::path& dir) {
         Mesh mesh = Triangle();
         mesh.vertices[2][1] = kNan;
         return OutcomeOf(WriteMesh((dir / "m.off").string(), mesh));
       },
       E::kInvalidInput,
       {"{dir}/m.off", "vertex 2"}});
  add({"write_mesh_face_index_out_of_range",
       [](const fs::path& dir) {
         Mesh mesh = Triangle();
         mesh.face_indices[1] = 3;
         return OutcomeOf(WriteMesh((dir / "m.obj").string(), mesh));
       },
       E::kInvalidInput,
       {"{dir}/m.obj", "face 0"}});
  add({"write_scene_observation_out_of_range",
       [](const fs::path& dir) {
         SceneData scene = CubeData();
         scene.observations.back().viewpoint = 9;
         return OutcomeOf(WriteScene((dir / "s.json").string(), scene));
       },
       E::kInvalidInput,
       {"{dir}/s.json", "observations[95].viewpoint = 9"}});
  add({"write_scene_onto_a_directory",
       [](const fs::path& dir) {
         fs::create_directory(dir / "d.json");
         return OutcomeOf(WriteScene((dir / "d.json").string(), CubeData()));
       },
       E::kInvalidInput,
       {"{dir}/d.json"}});
  return cases;
}

/// Every regular file and directory under `dir`.
std::set<std::string> Listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    names.insert(fs::relative(entry.path(), dir).string());
  }
  return names;
}

std::string Expand(std::string text, const fs::path& dir) {
  const std::string key = "{dir}";
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key)) {
    text.replace(at, key.size(), dir.string());
  }
  return text;
}

class FacadeApi : public ::testing::TestWithParam<FacadeCase> {};

TEST_P(FacadeApi, ReturnsTheErrorNamingThePlaceSilentlyAndWritesNothing) {
  const FacadeCase& c = GetParam();
  RecordVerdict("library API", ExitCodeOf(c.expected));
  const fs::path dir = testing::FreshTempDir();
  const auto before = Listing(dir);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const Outcome outcome = c.run(dir);
  const std::string printed =
      ::testing::internal::GetCapturedStdout() + ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "") << "the library printed";
  ASSERT_FALSE(outcome.ok) << c.name << ": succeeded";
  const std::string text = outcome.error.ToString();
  EXPECT_EQ(outcome.error.code, c.expected) << ErrorCodeName(outcome.error.code) << ": " << text;
  EXPECT_FALSE(outcome.error.message.empty());
  for (const std::string& part : c.message) {
    EXPECT_NE(text.find(Expand(part, dir)), std::string::npos)
        << "'" << Expand(part, dir) << "' not named in: " << text;
  }
  // A failed call leaves the directory as it found it (files the case itself made aside).
  std::set<std::string> made = Listing(dir);
  for (const std::string& name :
       {std::string("bad.json"), std::string("lines.xyz"), std::string("d.json")}) {
    made.erase(name);
  }
  EXPECT_EQ(made, before) << "a failed call left files behind";
}

INSTANTIATE_TEST_SUITE_P(Hostile,
                         FacadeApi,
                         ::testing::ValuesIn(FacadeCases()),
                         [](const auto& info) { return info.param.name; });

/// A failed write leaves an older file of the same name as it was.
TEST(FacadeApi, FailedWriteKeepsTheOlderFile) {
  RecordVerdict("library API", 3);
  const fs::path dir = testing::FreshTempDir();
  const fs::path path = dir / "m.ply";
  ASSERT_TRUE(WriteMesh(path.string(), Triangle()).has_value());
  const std::string bytes = testing::Slurp(path);
  Mesh bad = Triangle();
  bad.vertices[0][0] = kInf;
  const Status s = WriteMesh(path.string(), bad);
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
  EXPECT_TRUE(testing::Slurp(path) == bytes) << "the older file was changed";
  EXPECT_EQ(Listing(dir), std::set<std::string>{"m.ply"});
}

}  // namespace
}  // namespace linesurf::robustness
