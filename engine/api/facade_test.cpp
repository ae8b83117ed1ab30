// The facade through the shared library (linesurf/linesurf.h): options validation, index
// checks, equality with the engine's pipeline, re-solve, silence and cancellation.

#include "linesurf/linesurf.h"

#include "engine/api/options_conversion.h"
#include "engine/core/run_context.h"
#include "engine/io/read_scene.h"
#include "engine/pipeline/reconstruct.h"
#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace linesurf {
namespace {

/// The options of the bundled example (tools/run_example.sh): planes detected, exterior scene.
ReconstructOptions HouseOptions() {
  ReconstructOptions o;
  o.scene_mode = SceneMode::kExterior;
  return o;
}

ReadSceneResult ReadHouse() {
  Expected<ReadSceneResult> read = ReadScene(testing::ExampleHouseInput().string());
  EXPECT_TRUE(read.has_value()) << (read ? "" : read.error().ToString());
  return read ? std::move(read.value()) : ReadSceneResult{};
}

/// A tiny valid scene: one segment seen from one viewpoint.
struct TinyScene {
  std::vector<Segment> segments{{{0, 0, 0}, {1, 0, 0}}};
  std::vector<Vector3> viewpoints{{0, -5, 0}};
  std::vector<Observation> observations{{0, 0}};
  InputScene View() const { return {segments, viewpoints, observations, {}, {}}; }
};

std::string Slurp(const std::filesystem::path& path) { return testing::Slurp(path); }

TEST(FacadeOptions, DefaultsAreValid) {
  EXPECT_TRUE(ReconstructOptions{}.Validate().has_value());
  EXPECT_TRUE(DetectOptions{}.Validate().has_value());
}

/// The engine holds the facade's detection, weight and quality structs; the other fields the
/// facade mirrors must keep the engine's defaults.
TEST(FacadeOptions, DefaultsAreTheEngines) {
  const ReconstructOptions o;
  const pipeline::ReconstructOptions e;
  EXPECT_EQ(o.plane_source == PlaneSource::kGiven, e.use_given_planes);
  EXPECT_EQ(o.sigma, e.energy.sigma);
  EXPECT_EQ(o.samples_per_sigma, e.energy.samples_per_sigma);
  EXPECT_EQ(o.structural_as_textural, e.energy.structural_as_textural);
  EXPECT_EQ(o.solver.backend, e.solver.backend);
  EXPECT_EQ(o.solver.time_limit_seconds, e.solver.time_limit_seconds);
  EXPECT_EQ(o.scene_mode, e.scene_mode);
  EXPECT_EQ(o.engine == ComplexEngine::kMonolithic, e.blocks.one_block);
  EXPECT_EQ(o.block_size, e.blocks.block_size);
  EXPECT_EQ(o.block_margin, e.blocks.support.margin_blocks);
  EXPECT_EQ(o.box_margin, e.box_margin);
  EXPECT_EQ(o.measure_quality, e.measure_quality);
  EXPECT_EQ(o.remove_floating_fragments, e.remove_floating_fragments);
  EXPECT_EQ(o.triangulate, e.triangulate);
  EXPECT_EQ(o.merge_coplanar, e.merge_coplanar);
  EXPECT_EQ(o.num_threads, e.num_threads);
  EXPECT_EQ(o.seed, e.seed);
}

/// Every bound of the schema is accepted by the engine's own checks too (the values the facade
/// lets through reach no second, narrower rule), and a value past it is refused naming the path.
TEST(FacadeOptions, SchemaBoundsAreTheEngines) {
  ReconstructOptions probe;
  std::vector<std::string> paths;
  VisitOptions(probe, [&](const OptionSpec& spec, auto& field) {
    using T = std::remove_cvref_t<decltype(field)>;
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      paths.emplace_back(spec.path);
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      paths.emplace_back(spec.path);
    }
  });
  ASSERT_GT(paths.size(), 30u);
  for (const std::string& path : paths) {
    for (const bool at_min : {true, false}) {
      ReconstructOptions inside, outside;
      bool bounded = false;
      auto set = [&](ReconstructOptions& o, bool past) {
        VisitOptions(o, [&](const OptionSpec& spec, auto& field) {
          if (spec.path != path) return;
          using T = std::remove_cvref_t<decltype(field)>;
          const OptionRange& r = spec.range;
          const double bound = at_min ? r.min : r.max;
          if (!std::isfinite(bound)) return;
          bounded = true;
          const bool open = at_min ? r.min_open : r.max_open;
          const double step =
              std::is_same_v<T, std::optional<double>> || std::is_floating_point_v<T>
                  ? std::max(1e-9, std::abs(bound) * 1e-9)
                  : 1.0;
          const double toward = at_min ? step : -step;
          const double value =
              past ? (open ? bound : bound - toward) : (open ? bound + toward : bound);
          if constexpr (std::is_same_v<T, std::optional<double>>) {
            field = value;
          } else {
            field = static_cast<T>(value);
          }
        });
      };
      set(inside, false);
      if (!bounded) continue;
      set(outside, true);
      if (path == "block_size" || path == "detection.block_size")
        inside.engine = ComplexEngine::kBlocks;
      EXPECT_TRUE(inside.Validate().has_value())
          << path << (at_min ? " min" : " max") << ": " << inside.Validate().error().ToString();
      const Status engine = api::ToEngineOptions(inside).Validate();
      EXPECT_TRUE(engine.has_value()) << path << (at_min ? " min" : " max") << ": "
                                      << (engine ? "" : engine.error().ToString());
      const Status refused = outside.Validate();
      ASSERT_FALSE(refused.has_value()) << path << (at_min ? " min" : " max");
      EXPECT_NE(refused.error().message.find(path), std::string::npos) << refused.error().message;
    }
  }
}

TEST(FacadeOptions, ValidateNamesTheFirstOffendingField) {
  struct Case {
    std::string field;
    void (*spoil)(ReconstructOptions&);
  };
  const Case cases[] = {
      {"epsilon", [](ReconstructOptions& o) { o.detection.epsilon = -1.0; }},
      {"relative_epsilon", [](ReconstructOptions& o) { o.detection.relative_epsilon = 0.7; }},
      {"epsilon_over_noise", [](ReconstructOptions& o) { o.detection.epsilon_over_noise = 0.0; }},
      {"max_planes", [](ReconstructOptions& o) { o.detection.max_planes = 0; }},
      {"weights.visibility", [](ReconstructOptions& o) { o.weights.visibility = -0.1; }},
      {"weights.corner", [](ReconstructOptions& o) { o.weights.corner = std::nan(""); }},
      {"sigma", [](ReconstructOptions& o) { o.sigma = 0.0; }},
      {"samples_per_sigma", [](ReconstructOptions& o) { o.samples_per_sigma = 0.0; }},
      {"solver.backend", [](ReconstructOptions& o) { o.solver.backend = SolverBackend(42); }},
      {"solver.time_limit_seconds",
       [](ReconstructOptions& o) { o.solver.time_limit_seconds = -1.0; }},
      {"scene_mode", [](ReconstructOptions& o) { o.scene_mode = SceneMode(7); }},
      {"engine", [](ReconstructOptions& o) { o.engine = ComplexEngine(3); }},
      {"block_size", [](ReconstructOptions& o) { o.block_size = -1.0; }},
      {"block_size",
       [](ReconstructOptions& o) {
         o.engine = ComplexEngine::kMonolithic;
         o.block_size = 3.0;
       }},
      {"merge_coplanar",
       [](ReconstructOptions& o) {
         o.merge_coplanar = true;
         o.triangulate = true;
       }},
      {"support_gap", [](ReconstructOptions& o) { o.detection.support_gap = -1.0; }},
      {"weights.open_seam", [](ReconstructOptions& o) { o.weights.open_seam = 1e7; }},
      {"weights.crease", [](ReconstructOptions& o) { o.weights.crease = -0.5; }},
      {"block_margin", [](ReconstructOptions& o) { o.block_margin = 65; }},
      {"box_margin", [](ReconstructOptions& o) { o.box_margin = 0.0; }},
      {"quality.fit_factor", [](ReconstructOptions& o) { o.quality.fit_factor = 0.0; }},
      {"quality.samples_per_segment",
       [](ReconstructOptions& o) { o.quality.samples_per_segment = 0; }},
      {"num_threads", [](ReconstructOptions& o) { o.num_threads = -2; }},
  };
  for (const Case& c : cases) {
    ReconstructOptions o;
    c.spoil(o);
    const Status s = o.Validate();
    ASSERT_FALSE(s.has_value()) << c.field;
    EXPECT_EQ(s.error().code, ErrorCode::kInvalidOptions) << c.field;
    EXPECT_NE(s.error().message.find(c.field), std::string::npos)
        << c.field << " not named in: " << s.error().ToString();
  }
  // Every value is checked against its spec, also one the run ignores (detection with given
  // planes): the same rule as the CLI's and the C API's.
  ReconstructOptions given;
  given.plane_source = PlaneSource::kGiven;
  given.detection.epsilon = -1.0;
  EXPECT_FALSE(given.Validate().has_value());
}

// The block ranges are the schema's, the block size against the engine is the engine's rule
// (ValidateEngineBlockSize); the messages name the facade's fields, as the CLI, the C API and
// Python show them.
TEST(FacadeOptions, BlockFieldsFollowTheEnginesRulesUnderTheFacadesNames) {
  const auto message = [](const std::function<void(ReconstructOptions&)>& spoil) {
    ReconstructOptions o;
    spoil(o);
    const Status s = o.Validate();
    EXPECT_FALSE(s.has_value());
    return s ? std::string() : s.error().ToString();
  };
  EXPECT_EQ(message([](ReconstructOptions& o) {
              o.engine = ComplexEngine::kMonolithic;
              o.block_size = 3.0;
            }),
            "options: block_size applies to the blocks engine only (per-block detection: "
            "detection.block_size)");
  for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(message([bad](ReconstructOptions& o) {
                o.engine = ComplexEngine::kBlocks;
                o.block_size = bad;
              }),
              "options: block_size must be >= 0")
        << bad;
  }
  EXPECT_EQ(message([](ReconstructOptions& o) {
              o.engine = ComplexEngine::kBlocks;
              o.block_margin = -1;
            }),
            "options: block_margin must be in [0, 64]");
  ReconstructOptions blocks;
  blocks.engine = ComplexEngine::kBlocks;
  blocks.block_size = 3.0;
  EXPECT_TRUE(blocks.Validate().has_value());
}

TEST(FacadeOptions, ReconstructRefusesInvalidOptions) {
  const TinyScene tiny;
  ReconstructOptions o;
  o.weights.edge = -1.0;
  const auto r = Reconstruct(tiny.View(), o);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(r.error().message.find("weights.edge"), std::string::npos) << r.error().ToString();
}

TEST(FacadeOptions, NamesRoundTrip) {
  for (SolverBackend b : {SolverBackend::kAuto,
                          SolverBackend::kClp,
                          SolverBackend::kMaxflow,
                          SolverBackend::kPdhg,
                          SolverBackend::kBand,
                          SolverBackend::kCbc,
                          SolverBackend::kClpBarrier,
                          SolverBackend::kBlocks,
                          SolverBackend::kPdhgEnergy}) {
    EXPECT_EQ(SolverBackendFromName(SolverBackendName(b)), b);
  }
  for (SceneMode m : {SceneMode::kExterior, SceneMode::kInterior, SceneMode::kAuto}) {
    EXPECT_EQ(SceneModeFromName(SceneModeName(m)), m);
  }
  EXPECT_EQ(PlaneSourceFromName("given"), PlaneSource::kGiven);
  EXPECT_FALSE(SolverBackendFromName("simplex").has_value());
}

TEST(FacadeInput, BadObservationIndexIsNamed) {
  TinyScene tiny;
  tiny.observations.push_back({0, 3});  // viewpoint 3 of 1
  auto r = Reconstruct(tiny.View(), ReconstructOptions{});
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(r.error().message.find("observations[1].viewpoint = 3"), std::string::npos)
      << r.error().ToString();

  tiny.observations = {{5, 0}};  // segment 5 of 1
  auto d = DetectPlanes(tiny.View(), DetectOptions{});
  ASSERT_FALSE(d.has_value());
  EXPECT_EQ(d.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(d.error().message.find("observations[0].segment = 5"), std::string::npos)
      << d.error().ToString();
}

TEST(FacadeInput, BadMembershipIndexIsNamed) {
  const TinyScene tiny;
  const std::vector<Plane> planes{Plane{{0, 0, 0}, {0, 0, 1}}};
  const std::vector<Membership> memberships{{0, 0}, {0, 1}};
  InputScene view = tiny.View();
  view.planes = planes;
  view.memberships = memberships;
  ReconstructOptions o;
  o.plane_source = PlaneSource::kGiven;
  auto r = Reconstruct(view, o);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(r.error().message.find("memberships[1].plane = 1"), std::string::npos)
      << r.error().ToString();
}

TEST(FacadeInput, GivenPlanesNeedPlanes) {
  const TinyScene tiny;
  ReconstructOptions o;
  o.plane_source = PlaneSource::kGiven;
  auto r = Reconstruct(tiny.View(), o);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidInput) << r.error().ToString();
}

TEST(FacadeIo, ReadSceneNamesTheMissingFile) {
  auto r = ReadScene("/nonexistent/lines.json");
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().ToString().find("/nonexistent/lines.json"), std::string::npos)
      << r.error().ToString();
}

TEST(FacadeIo, WriteMeshRefusesBrokenOffsets) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.face_offsets = {0, 4};
  mesh.face_indices = {0, 1, 2};
  const Status s = WriteMesh((testing::FreshTempDir() / "m.ply").string(), mesh);
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
}

TEST(FacadeIo, ReadMeshReadsWhatWriteMeshWrote) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.5, -0.0}};
  mesh.face_offsets = {0, 3, 6};
  mesh.face_indices = {0, 1, 2, 1, 3, 2};
  const auto dir = testing::FreshTempDir();
  for (const char* name : {"m.ply", "m.obj", "m.off"}) {
    const std::string path = (dir / name).string();
    ASSERT_TRUE(WriteMesh(path, mesh).has_value()) << name;
    const Expected<Mesh> back = ReadMesh(path);
    ASSERT_TRUE(back.has_value()) << back.error().ToString();
    EXPECT_EQ(back->vertices, mesh.vertices) << name;
    EXPECT_EQ(back->face_offsets, mesh.face_offsets) << name;
    EXPECT_EQ(back->face_indices, mesh.face_indices) << name;
  }
  const Expected<Mesh> missing = ReadMesh((dir / "none.ply").string());
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(missing.error().message.find("none.ply"), std::string::npos)
      << missing.error().ToString();
}

TEST(FacadeIo, SceneRoundTripsThroughWriteScene) {
  const ReadSceneResult house = ReadHouse();
  ASSERT_FALSE(house.scene.segments.empty());
  const auto path = testing::FreshTempDir() / "copy.json";
  ASSERT_TRUE(WriteScene(path.string(), house.scene).has_value());
  const auto again = ReadScene(path.string());
  ASSERT_TRUE(again.has_value()) << again.error().ToString();
  const SceneData& a = house.scene;
  const SceneData& b = again->scene;
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    EXPECT_EQ(a.segments[i].p1, b.segments[i].p1);
    EXPECT_EQ(a.segments[i].p2, b.segments[i].p2);
  }
  EXPECT_EQ(a.viewpoints, b.viewpoints);
  ASSERT_EQ(a.observations.size(), b.observations.size());
  ASSERT_EQ(a.memberships.size(), b.memberships.size());
  for (std::size_t i = 0; i < a.memberships.size(); ++i) {
    EXPECT_EQ(a.memberships[i].segment, b.memberships[i].segment);
    EXPECT_EQ(a.memberships[i].plane, b.memberships[i].plane);
  }
}

// Membership lists without a membership or a plane (reference JSON: empty plane_index lists, no
// planes) are a state of the scene: read, sanitised and written back; without them nothing is
// invented.
TEST(FacadeIo, EmptyMembershipListsWithoutPlanesRoundTrip) {
  SceneData scene;
  scene.segments = {{{0, 0, 0}, {2, 0, 0}}, {{0, 0, 1}, {0, 0, 3}}};
  scene.viewpoints = {{0, 5, 0}};
  scene.observations = {{0, 0}, {1, 0}};
  scene.has_memberships = true;
  const auto dir = testing::FreshTempDir();
  ASSERT_TRUE(WriteScene((dir / "a.json").string(), scene).has_value());
  const std::string json = Slurp(dir / "a.json");
  EXPECT_NE(json.find("\"plane_index\": []}"), std::string::npos) << json;
  EXPECT_NE(json.find("\"planes\": []"), std::string::npos) << json;
  const auto read = ReadScene((dir / "a.json").string());
  ASSERT_TRUE(read.has_value()) << read.error().ToString();
  EXPECT_TRUE(read->scene.has_memberships);
  EXPECT_TRUE(read->scene.memberships.empty());
  const auto sane = SanitizeScene(read->scene);
  ASSERT_TRUE(sane.has_value()) << sane.error().ToString();
  EXPECT_TRUE(sane->scene.has_memberships);

  scene.has_memberships = false;
  ASSERT_TRUE(WriteScene((dir / "b.json").string(), scene).has_value());
  EXPECT_EQ(Slurp(dir / "b.json").find("plane"), std::string::npos);
  const auto bare = ReadScene((dir / "b.json").string());
  ASSERT_TRUE(bare.has_value()) << bare.error().ToString();
  EXPECT_FALSE(bare->scene.has_memberships);
}

TEST(FacadeInput, SanitizeSceneDropsBadSegmentsAndMapsTheRest) {
  SceneData scene;
  scene.segments = {{{0, 0, 0}, {1, 0, 0}},
                    {{2, 2, 2}, {2, 2, 2}},  // zero length
                    {{0, 0, std::nan("")}, {0, 1, 0}},
                    {{0, 1, 0}, {0, 1, 1}}};
  scene.viewpoints = {{0, -5, 0}};
  scene.observations = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  const auto sane = SanitizeScene(scene);
  ASSERT_TRUE(sane.has_value()) << sane.error().ToString();
  EXPECT_EQ(sane->input_segment, (std::vector<std::uint32_t>{0, 3}));
  ASSERT_EQ(sane->scene.segments.size(), 2u);
  EXPECT_EQ(sane->scene.segments[1].p2, (Vector3{0, 1, 1}));  // world coordinates again
  EXPECT_GE(sane->warnings.size(), 2u);                       // non-finite, zero length
}

/// The facade's mesh is the pipeline's, vertex for vertex and face for face.
TEST(FacadeReconstruct, HouseEqualsThePipeline) {
  const ReadSceneResult house = ReadHouse();
  const ReconstructOptions options = HouseOptions();
  const auto facade = Reconstruct(house.scene.View(), options);
  ASSERT_TRUE(facade.has_value()) << facade.error().ToString();

  Expected<Scene> scene = io::ReadScene(testing::ExampleHouseInput(), {});
  ASSERT_TRUE(scene.has_value()) << scene.error().ToString();
  pipeline::ReconstructOptions engine_options;
  engine_options.scene_mode = pipeline::SceneMode::kExterior;
  const RunContext ctx;
  const auto engine = pipeline::Reconstruct(*scene, engine_options, ctx);
  ASSERT_TRUE(engine.has_value()) << engine.error().ToString();

  const Mesh& m = facade->mesh;
  ASSERT_GT(m.NumFaces(), 0u);
  ASSERT_EQ(m.vertices.size(), engine->mesh.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    for (int a = 0; a < 3; ++a) EXPECT_EQ(m.vertices[v][a], engine->mesh.vertices[v][a]);
  }
  EXPECT_EQ(m.face_offsets, engine->mesh.face_offsets);
  EXPECT_EQ(m.face_indices, engine->mesh.face_indices);
  EXPECT_TRUE(facade->stats.surface.mesh_closed);
  EXPECT_TRUE(facade->stats.surface.mesh_manifold);
  EXPECT_EQ(facade->stats.complex.cells, engine->stats.complex.cells);
  // The run's eps and quality figures come out as the engine reports them.
  EXPECT_FALSE(facade->stats.detection.epsilon.source.empty());
  EXPECT_EQ(facade->stats.detection.epsilon.source, engine->stats.detection.epsilon.source);
  EXPECT_EQ(facade->stats.detection.epsilon.epsilon, engine->stats.detection.epsilon.epsilon);
  ASSERT_TRUE(facade->stats.quality.measured);
  EXPECT_EQ(facade->stats.quality.data_fit, engine->stats.quality.data_fit);
  EXPECT_EQ(facade->stats.quality.components.size(), engine->stats.quality.components.size());
  EXPECT_EQ(facade->stats.labeling.lower_bound_source, engine->stats.labeling.lower_bound_source);
  EXPECT_EQ(facade->planes.size(), engine->planes.size());
  // Every membership names an input segment and a returned plane, at most two per segment.
  std::vector<int> per_segment(house.scene.segments.size(), 0);
  for (const Membership& mb : facade->memberships) {
    ASSERT_LT(mb.segment, per_segment.size());
    ASSERT_LT(mb.plane, facade->planes.size());
    EXPECT_LE(++per_segment[mb.segment], 2);
  }
  EXPECT_FALSE(facade->memberships.empty());
}

TEST(FacadeEvaluate, AMeshAgainstItselfIsPerfectAndBadOptionsAreNamed) {
  const ReadSceneResult house = ReadHouse();
  const auto result = Reconstruct(house.scene.View(), HouseOptions());
  ASSERT_TRUE(result.has_value()) << result.error().ToString();
  EvaluationOptions options;
  options.samples_per_mesh = 5000;
  const Expected<EvaluationResult> self = EvaluateMesh(result->mesh, result->mesh, options);
  ASSERT_TRUE(self.has_value()) << self.error().ToString();
  ASSERT_EQ(self->precision.size(), options.thresholds.size());
  for (std::size_t i = 0; i < options.thresholds.size(); ++i) {
    EXPECT_EQ(self->precision[i], 1.0);
    EXPECT_EQ(self->completeness[i], 1.0);
  }
  EXPECT_TRUE(self->topology.closed);
  EXPECT_EQ(self->num_visible_gt_samples, self->num_gt_samples);
  // Restricted to what the viewpoints see, completeness counts fewer ground-truth samples.
  const Expected<EvaluationResult> seen =
      EvaluateMesh(result->mesh, result->mesh, options, house.scene.viewpoints);
  ASSERT_TRUE(seen.has_value()) << seen.error().ToString();
  EXPECT_LT(seen->num_visible_gt_samples, seen->num_gt_samples);
  EXPECT_GT(seen->num_visible_gt_samples, 0u);

  options.thresholds = {0.1, 0.05};
  const Expected<EvaluationResult> bad = EvaluateMesh(result->mesh, result->mesh, options);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(bad.error().message.find("increasing"), std::string::npos);
  options.thresholds = {0.05};
  options.num_threads = kMaxThreads + 1;
  EXPECT_EQ(EvaluateMesh(result->mesh, result->mesh, options).error().code,
            ErrorCode::kInvalidOptions);
}

/// The figures without ground truth of a result, measured again from its planes and memberships,
/// are those the run reported.
TEST(FacadeEvaluate, QualityOfAResultIsTheRunsOwn) {
  const ReadSceneResult house = ReadHouse();
  const auto result = Reconstruct(house.scene.View(), HouseOptions());
  ASSERT_TRUE(result.has_value()) << result.error().ToString();
  ASSERT_TRUE(result->stats.quality.measured);
  SceneData lines = house.scene;
  lines.planes = result->planes;
  lines.memberships = result->memberships;
  lines.has_memberships = true;
  DetectOptions options;
  options.detection.epsilon = result->stats.detection.epsilon.epsilon;
  const Expected<SurfaceQuality> quality = MeasureSurfaceQuality(result->mesh, lines, options);
  ASSERT_TRUE(quality.has_value()) << quality.error().ToString();
  EXPECT_EQ(quality->epsilon, result->stats.detection.epsilon.epsilon);
  EXPECT_NEAR(quality->data_fit, result->stats.quality.data_fit, 1e-9);
  EXPECT_NEAR(quality->visibility_consistency, result->stats.quality.visibility_consistency, 1e-9);
  EXPECT_EQ(quality->components.size(), result->stats.quality.components.size());
  EXPECT_EQ(quality->floating_fragments, result->stats.quality.floating_fragments);

  // Without planes they are detected; eps is estimated when not given.
  SceneData bare = house.scene;
  bare.planes.clear();
  bare.memberships.clear();
  bare.has_memberships = false;
  const Expected<SurfaceQuality> detected = MeasureSurfaceQuality(result->mesh, bare);
  ASSERT_TRUE(detected.has_value()) << detected.error().ToString();
  EXPECT_GT(detected->epsilon, 0.0);
  EXPECT_GT(detected->data_fit, 0.9);

  DetectOptions bad;
  bad.detection.epsilon = -1.0;
  EXPECT_EQ(MeasureSurfaceQuality(result->mesh, bare, bad).error().code,
            ErrorCode::kInvalidOptions);
}

/// The bytes of WriteMesh are those of `linesurf reconstruct` (the CLI on the engine).
TEST(FacadeReconstruct, HouseMeshBytesEqualTheCli) {
  if (!std::filesystem::exists(testing::BinDir() / "linesurf")) {
    GTEST_SKIP() << "the linesurf executable is not built (LINESURF_BUILD_CLI=OFF)";
  }
  const auto dir = testing::FreshTempDir();
  const auto cli = testing::RunLinesurf(
      "reconstruct " + testing::ShellQuote(testing::ExampleHouseInput().string()) +
          " --scene exterior -o " + testing::ShellQuote((dir / "cli.ply").string()),
      dir);
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  const ReadSceneResult house = ReadHouse();
  const auto r = Reconstruct(house.scene.View(), HouseOptions());
  ASSERT_TRUE(r.has_value()) << r.error().ToString();
  ASSERT_TRUE(WriteMesh((dir / "facade.ply").string(), r->mesh).has_value());
  const std::string facade_bytes = Slurp(dir / "facade.ply");
  EXPECT_FALSE(facade_bytes.empty());
  EXPECT_TRUE(facade_bytes == Slurp(dir / "cli.ply"));
}

TEST(FacadeReconstruct, ResolveWithTheSameWeightsEqualsReconstruct) {
  const ReadSceneResult house = ReadHouse();
  const ReconstructOptions options = HouseOptions();
  const auto direct = Reconstruct(house.scene.View(), options);
  ASSERT_TRUE(direct.has_value()) << direct.error().ToString();
  auto prepared = Reconstruction::Prepare(house.scene.View(), options);
  ASSERT_TRUE(prepared.has_value()) << prepared.error().ToString();
  const auto again = prepared->Solve(options.weights);
  ASSERT_TRUE(again.has_value()) << again.error().ToString();
  EXPECT_EQ(again->mesh.vertices, direct->mesh.vertices);
  EXPECT_EQ(again->mesh.face_indices, direct->mesh.face_indices);
  EXPECT_EQ(again->mesh.face_offsets, direct->mesh.face_offsets);

  // Other weights, same complex: a different labelling from the same cells.
  EnergyWeights heavy = options.weights;
  heavy.visibility = 10.0;
  heavy.edge = 1.0;
  const auto other = prepared->Solve(heavy);
  ASSERT_TRUE(other.has_value()) << other.error().ToString();
  EXPECT_EQ(other->stats.complex.cells, direct->stats.complex.cells);
  EXPECT_NE(other->stats.labeling.objective, direct->stats.labeling.objective);
  // ... equal to a fresh reconstruction with those weights.
  ReconstructOptions heavy_options = options;
  heavy_options.weights = heavy;
  const auto fresh = Reconstruct(house.scene.View(), heavy_options);
  ASSERT_TRUE(fresh.has_value()) << fresh.error().ToString();
  EXPECT_EQ(other->mesh.vertices, fresh->mesh.vertices);
  EXPECT_EQ(other->mesh.face_indices, fresh->mesh.face_indices);

  EnergyWeights bad = options.weights;
  bad.area = -1.0;
  const auto refused = prepared->Solve(bad);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().code, ErrorCode::kInvalidOptions);
  EXPECT_NE(refused.error().message.find("weights.area"), std::string::npos);
}

TEST(FacadeDetect, HousePlanesIndexInputSegments) {
  const ReadSceneResult house = ReadHouse();
  const auto d = DetectPlanes(house.scene.View(), DetectOptions{});
  ASSERT_TRUE(d.has_value()) << d.error().ToString();
  EXPECT_GE(d->planes.size(), 7u);  // 4 walls, 2 roof sides, ground or gables
  EXPECT_EQ(d->support.size(), d->planes.size());
  EXPECT_EQ(d->stats.input_segments, house.scene.segments.size());
  for (const Membership& m : d->memberships) {
    ASSERT_LT(m.segment, house.scene.segments.size());
    ASSERT_LT(m.plane, d->planes.size());
  }
}

/// Redirects file descriptors 1 and 2 to files while alive (so writes of any thread through
/// stdio, iostreams or write(2) are caught); Captured() restores them and returns both.
class CaptureStdio {
 public:
  explicit CaptureStdio(const std::filesystem::path& dir)
      : out_path_(dir / "stdout.txt"), err_path_(dir / "stderr.txt") {
    std::fflush(stdout);
    std::fflush(stderr);
    std::cout.flush();
    std::cerr.flush();
    saved_out_ = dup(1);
    saved_err_ = dup(2);
    Redirect(out_path_, 1);
    Redirect(err_path_, 2);
  }
  std::string Captured() {
    std::fflush(stdout);
    std::fflush(stderr);
    std::cout.flush();
    std::cerr.flush();
    dup2(saved_out_, 1);
    dup2(saved_err_, 2);
    close(saved_out_);
    close(saved_err_);
    return Slurp(out_path_) + Slurp(err_path_);
  }

 private:
  static void Redirect(const std::filesystem::path& path, int fd) {
    const int file = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(file, 0) << path;
    ASSERT_GE(dup2(file, fd), 0) << path;
    close(file);
  }

  std::filesystem::path out_path_, err_path_;
  int saved_out_ = -1;
  int saved_err_ = -1;
};

/// The capture itself catches what a library could print: stdio, iostreams, raw write(2).
TEST(FacadeReconstruct, CaptureStdioCatchesEveryWayOfPrinting) {
  CaptureStdio capture(testing::FreshTempDir());
  std::fputs("a", stdout);
  std::cerr << "b";
  ASSERT_EQ(write(2, "c", 1), 1);
  std::thread([] { std::printf("d"); }).join();
  EXPECT_EQ(capture.Captured(), "adbc");
}

/// A full library session prints nothing: read, reconstruct (with progress and logging
/// callbacks unset and set), detect, prepare and re-solve, a failing call, write.
TEST(FacadeReconstruct, WritesNothingToStdoutOrStderr) {
  const std::filesystem::path dir = testing::FreshTempDir();
  ReconstructOptions options = HouseOptions();
  int progress_calls = 0;
  RunControl control;
  control.on_progress = [&progress_calls](const Progress&) { ++progress_calls; };
  CaptureStdio capture(dir);
  const auto house = ReadScene(testing::ExampleHouseInput().string());
  const auto silent = Reconstruct(house->scene.View(), options);
  const auto r = Reconstruct(house->scene.View(), options, control);
  const auto d = DetectPlanes(house->scene.View(), DetectOptions{});
  const auto prepared = Reconstruction::Prepare(house->scene.View(), options);
  EnergyWeights weights = options.weights;
  weights.visibility = 0.5;
  Expected<ReconstructResult> solved = Error{ErrorCode::kInternal, "test", "not prepared"};
  if (prepared) solved = prepared->Solve(weights);
  const auto bad = Reconstruct(InputScene{}, options);
  const Status written = r ? WriteMesh((dir / "house.ply").string(), r->mesh) : Status{};
  const std::string printed = capture.Captured();
  ASSERT_TRUE(house.has_value()) << house.error().ToString();
  ASSERT_TRUE(silent.has_value()) << silent.error().ToString();
  ASSERT_TRUE(r.has_value()) << r.error().ToString();
  ASSERT_TRUE(d.has_value()) << d.error().ToString();
  ASSERT_TRUE(prepared.has_value()) << prepared.error().ToString();
  ASSERT_TRUE(solved.has_value()) << solved.error().ToString();
  ASSERT_TRUE(written.has_value()) << written.error().ToString();
  EXPECT_FALSE(bad.has_value());
  EXPECT_GT(progress_calls, 0);
  EXPECT_EQ(printed, "") << "the library printed";
}

TEST(FacadeReconstruct, CallbacksAreNeverCalledConcurrently) {
  const ReadSceneResult house = ReadHouse();
  ReconstructOptions options = HouseOptions();
  options.num_threads = 4;
  std::atomic<int> inside{0};
  std::atomic<bool> overlap{false};
  std::atomic<int> calls{0};
  const auto enter = [&] {
    if (inside.fetch_add(1) != 0) overlap = true;
    ++calls;
    std::this_thread::sleep_for(std::chrono::microseconds(50));
    inside.fetch_sub(1);
  };
  RunControl control;
  control.on_progress = [&](const Progress&) { enter(); };
  control.is_cancelled = [&] {
    enter();
    return false;
  };
  const auto r = Reconstruct(house.scene.View(), options, control);
  ASSERT_TRUE(r.has_value()) << r.error().ToString();
  EXPECT_GT(calls.load(), 10);
  EXPECT_FALSE(overlap.load());
}

TEST(FacadeReconstruct, ThrowingProgressCallbackCancels) {
  const ReadSceneResult house = ReadHouse();
  RunControl control;
  control.on_progress = [](const Progress&) { throw std::runtime_error("host bug"); };
  const auto r = Reconstruct(house.scene.View(), HouseOptions(), control);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kCancelled) << r.error().ToString();
}

/// Cancel requested from the progress callback during the cell complex of Andalusian (148
/// given planes, ~3e5 cells), early and late: the call returns kCancelled without starting
/// another stage and within the plane insertion that was under way (the complex polls inside
/// insertions). Counted in work, not time; the latency is BM_CancelLatencyAndalusian's
/// (tests/bench/api_bench.cpp).
TEST(FacadeReconstruct, CancelFromProgressOnAndalusianStopsWithinOnePlaneInsertion) {
  LINESURF_REQUIRE_ANDALUSIAN(input);
  const auto read = ReadScene(input.string());
  ASSERT_TRUE(read.has_value()) << read.error().ToString();
  ASSERT_FALSE(read->scene.planes.empty());
  const double one_plane = 1.0 / static_cast<double>(read->scene.planes.size());
  ReconstructOptions options;
  options.plane_source = PlaneSource::kGiven;
  for (const double at : {0.3, 0.9}) {
    std::atomic<bool> cancel{false};
    double requested_fraction = 0.0;
    double furthest_fraction = 0.0;
    std::vector<std::string> later_stages;
    RunControl control;
    control.on_progress = [&](const Progress& p) {
      if (cancel) {
        if (p.stage != "cell_complex") later_stages.push_back(p.stage);
        furthest_fraction = std::max(furthest_fraction, p.stage_fraction);
      } else if (p.stage == "cell_complex" && p.stage_fraction >= at) {
        requested_fraction = furthest_fraction = p.stage_fraction;
        cancel = true;
      }
    };
    control.is_cancelled = [&] { return cancel.load(); };
    const auto r = Reconstruct(read->scene.View(), options, control);
    ASSERT_TRUE(cancel.load()) << "the run never reached " << at << " of the complex";
    ASSERT_FALSE(r.has_value()) << "the run finished although cancelled at " << at;
    EXPECT_EQ(r.error().code, ErrorCode::kCancelled) << r.error().ToString();
    EXPECT_TRUE(later_stages.empty())
        << "stage " << later_stages.front() << " ran after the cancel request at " << at;
    EXPECT_LE(furthest_fraction - requested_fraction, one_plane)
        << "the complex went on from " << requested_fraction << " to " << furthest_fraction
        << " after the cancel request (one plane is " << one_plane << ")";
  }
}

}  // namespace
}  // namespace linesurf
