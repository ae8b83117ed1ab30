// The C API (linesurf/linesurf_c.h) through the shared library: errors, option setters, the
// house, callbacks.

#include "linesurf/linesurf_c.h"

#include "linesurf/linesurf.h"

#include "tests/support/cli_runner.h"
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace linesurf {
namespace {

/// Blocks of the house for the blocks-engine test: several blocks, a margin other than the
/// default.
constexpr double kHouseBlockSize = 6.0;
constexpr int kHouseBlockMargin = 2;

/// Owns a linesurf_error* and frees it.
struct ErrorHolder {
  linesurf_error* error = nullptr;
  ~ErrorHolder() { linesurf_error_free(error); }
  std::string Message() const { return linesurf_error_message(error); }
};

TEST(CApi, StatusNamesFollowTheErrorCodes) {
  EXPECT_STREQ(linesurf_status_name(LINESURF_OK), "ok");
  EXPECT_STREQ(linesurf_status_name(LINESURF_ERROR_CANCELLED), "cancelled");
  EXPECT_STREQ(linesurf_status_name(LINESURF_ERROR_INTERNAL), "internal");
  EXPECT_STREQ(linesurf_status_name(99), "unknown");
  EXPECT_STREQ(linesurf_status_name(-1), "unknown");
  EXPECT_STREQ(linesurf_status_name(LINESURF_ERROR_INTERNAL + 1), "unknown");
  EXPECT_STREQ(linesurf_version(), LINESURF_VERSION_STRING);
}

TEST(CApi, OptionSettersNameWhatIsWrong) {
  linesurf_options* options = linesurf_options_create();
  ASSERT_NE(options, nullptr);
  {
    ErrorHolder e;
    EXPECT_EQ(linesurf_options_set_number(options, "weights.visibility", 0.5, &e.error),
              LINESURF_OK);
    EXPECT_EQ(e.error, nullptr);
  }
  {
    ErrorHolder e;
    EXPECT_EQ(linesurf_options_set_number(options, "weights.visiblity", 0.5, &e.error),
              LINESURF_ERROR_INVALID_OPTIONS);
    EXPECT_NE(e.Message().find("weights.visiblity"), std::string::npos) << e.Message();
  }
  {
    ErrorHolder e;
    EXPECT_EQ(linesurf_options_set_number(options, "detection.max_planes", 2.5, &e.error),
              LINESURF_ERROR_INVALID_OPTIONS);
    EXPECT_NE(e.Message().find("detection.max_planes"), std::string::npos) << e.Message();
  }
  {
    ErrorHolder e;
    EXPECT_EQ(linesurf_options_set_string(options, "scene_mode", "sideways", &e.error),
              LINESURF_ERROR_INVALID_OPTIONS);
    EXPECT_NE(e.Message().find("sideways"), std::string::npos) << e.Message();
  }
  EXPECT_EQ(linesurf_options_set_string(options, "solver.backend", "clp", nullptr), LINESURF_OK);
  EXPECT_EQ(linesurf_options_set_number(options, "seed", -1.0, nullptr),
            LINESURF_ERROR_INVALID_OPTIONS);
  linesurf_options_free(options);
}

TEST(CApi, BadObservationIndexIsNamed) {
  const double segment[6] = {0, 0, 0, 1, 0, 0};
  const double viewpoint[3] = {0, -5, 0};
  const uint32_t observation[2] = {0, 4};
  ErrorHolder e;
  linesurf_scene* scene = linesurf_scene_create(segment, 1, viewpoint, 1, observation, 1, &e.error);
  ASSERT_NE(scene, nullptr) << e.Message();
  linesurf_options* options = linesurf_options_create();
  linesurf_result* result = linesurf_reconstruct(scene, options, nullptr, &e.error);
  EXPECT_EQ(result, nullptr);
  EXPECT_EQ(linesurf_error_code(e.error), LINESURF_ERROR_INVALID_INPUT);
  EXPECT_NE(e.Message().find("observations[0].viewpoint = 4"), std::string::npos) << e.Message();
  linesurf_options_free(options);
  linesurf_scene_free(scene);
  EXPECT_EQ(linesurf_scene_create(nullptr, 2, nullptr, 0, nullptr, 0, nullptr), nullptr);
}

TEST(CApi, MissingFileIsNamed) {
  ErrorHolder e;
  EXPECT_EQ(linesurf_scene_read("/nonexistent/x.json", nullptr, nullptr, &e.error), nullptr);
  EXPECT_EQ(linesurf_error_code(e.error), LINESURF_ERROR_INVALID_INPUT);
  EXPECT_NE(e.Message().find("/nonexistent/x.json"), std::string::npos) << e.Message();
}

/// The C result holds the C++ result's mesh and planes, value for value.
void ExpectSameMesh(const linesurf_result* result, const ReconstructResult& cpp) {
  ASSERT_EQ(linesurf_result_num_vertices(result), cpp.mesh.vertices.size());
  ASSERT_EQ(linesurf_result_num_faces(result), cpp.mesh.NumFaces());
  ASSERT_EQ(linesurf_result_num_planes(result), cpp.planes.size());
  const double* v = linesurf_result_vertices(result);
  for (std::size_t i = 0; i < cpp.mesh.vertices.size(); ++i) {
    for (int a = 0; a < 3; ++a) EXPECT_EQ(v[3 * i + a], cpp.mesh.vertices[i][a]);
  }
  const uint32_t* offsets = linesurf_result_face_offsets(result);
  const uint32_t* indices = linesurf_result_face_indices(result);
  EXPECT_EQ(std::vector<uint32_t>(offsets, offsets + cpp.mesh.face_offsets.size()),
            cpp.mesh.face_offsets);
  EXPECT_EQ(std::vector<uint32_t>(indices, indices + cpp.mesh.face_indices.size()),
            cpp.mesh.face_indices);
}

/// The message linesurf_reconstruct gives for `options` on a one-segment scene ("" on success).
std::string ReconstructMessage(const linesurf_options* options) {
  const double segment[6] = {0, 0, 0, 1, 0, 0};
  const double viewpoint[3] = {0, -5, 0};
  const uint32_t observation[2] = {0, 0};
  linesurf_scene* scene = linesurf_scene_create(segment, 1, viewpoint, 1, observation, 1, nullptr);
  EXPECT_NE(scene, nullptr);
  ErrorHolder e;
  linesurf_result* result = linesurf_reconstruct(scene, options, nullptr, &e.error);
  linesurf_result_free(result);
  linesurf_scene_free(scene);
  if (e.error == nullptr) return std::string();
  EXPECT_EQ(linesurf_error_code(e.error), LINESURF_ERROR_INVALID_OPTIONS);
  return e.Message();
}

// engine, block_size and block_margin reach the facade, which refuses bad values with its own
// messages (FacadeOptions.BlockFieldsFollowTheEnginesRulesUnderTheFacadesNames).
TEST(CApi, BlockOptionsAreCheckedByTheFacade) {
  linesurf_options* options = linesurf_options_create();
  ASSERT_NE(options, nullptr);
  {
    ErrorHolder e;
    EXPECT_EQ(linesurf_options_set_string(options, "engine", "voxels", &e.error),
              LINESURF_ERROR_INVALID_OPTIONS);
    EXPECT_EQ(e.Message(), "options: 'voxels' is not a value of engine");
  }
  ASSERT_EQ(linesurf_options_set_number(options, "block_margin", -0.5, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options), "options: block_margin must be in [0, 64]");
  ASSERT_EQ(linesurf_options_set_number(options, "block_margin", 0.25, nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_string(options, "engine", "monolithic", nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "block_size", 3.0, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options),
            "options: block_size applies to the blocks engine only (per-block detection: "
            "detection.block_size)");
  ASSERT_EQ(linesurf_options_set_string(options, "engine", "blocks", nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "block_size", -1.0, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options), "options: block_size must be >= 0");
  ASSERT_EQ(linesurf_options_set_number(options, "block_size", 3.0, nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "block_margin", 65.0, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options), "options: block_margin must be in [0, 64]");
  linesurf_options_free(options);
}

TEST(CApi, OptionalRealsAreSetAndCheckedByTheFacade) {
  linesurf_options* options = linesurf_options_create();
  ASSERT_NE(options, nullptr);
  ASSERT_EQ(linesurf_options_set_number(options, "weights.crease", -0.5, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options).rfind("options: weights.crease", 0), 0u);
  ASSERT_EQ(linesurf_options_set_number(options, "weights.crease", 0.2, nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "sigma", -1.0, nullptr), LINESURF_OK);
  EXPECT_EQ(ReconstructMessage(options).rfind("options: sigma", 0), 0u);
  linesurf_options_free(options);
}

/// The example house as a C scene, with C options for an exterior scene (the C++ side of the
/// comparisons uses SceneMode::kExterior); both freed at the end of the test.
struct CHouse {
  std::string path = testing::ExampleHouseInput().string();
  linesurf_scene* scene = linesurf_scene_read(path.c_str(), nullptr, nullptr, nullptr);
  linesurf_options* options = linesurf_options_create();
  CHouse() { linesurf_options_set_string(options, "scene_mode", "exterior", nullptr); }
  CHouse(const CHouse&) = delete;
  CHouse& operator=(const CHouse&) = delete;
  ~CHouse() {
    linesurf_options_free(options);
    linesurf_scene_free(scene);
  }
};

struct Calls {
  int progress = 0;
  int cancel_polls = 0;
  bool cancel = false;
};

TEST(CApi, HouseMatchesTheCppFacade) {
  const CHouse house;
  ASSERT_NE(house.scene, nullptr);
  ErrorHolder e;
  Calls calls;
  linesurf_callbacks callbacks{};
  callbacks.on_progress = [](const char*, double, void* user) {
    ++static_cast<Calls*>(user)->progress;
  };
  callbacks.is_cancelled = [](void* user) {
    ++static_cast<Calls*>(user)->cancel_polls;
    return 0;
  };
  callbacks.user_data = &calls;
  linesurf_result* result = linesurf_reconstruct(house.scene, house.options, &callbacks, &e.error);
  ASSERT_NE(result, nullptr) << e.Message();
  EXPECT_GT(calls.progress, 0);
  EXPECT_GT(calls.cancel_polls, 0);

  ReconstructOptions cpp_options;
  cpp_options.scene_mode = SceneMode::kExterior;
  const auto read = ReadScene(house.path);
  ASSERT_TRUE(read.has_value());
  const auto cpp = Reconstruct(read->scene.View(), cpp_options);
  ASSERT_TRUE(cpp.has_value()) << cpp.error().ToString();
  ExpectSameMesh(result, *cpp);
  EXPECT_EQ(linesurf_result_planes(result)[3], cpp->planes[0].normal[0]);

  const auto dir = testing::FreshTempDir();
  ASSERT_EQ(linesurf_result_write_mesh(result, (dir / "c.ply").c_str(), 0, &e.error), LINESURF_OK)
      << e.Message();
  ASSERT_TRUE(WriteMesh((dir / "cpp.ply").string(), cpp->mesh).has_value());
  EXPECT_TRUE(testing::Slurp(dir / "c.ply") == testing::Slurp(dir / "cpp.ply"));
  EXPECT_EQ(linesurf_result_write_mesh(result, (dir / "m.xyz").c_str(), 0, nullptr),
            LINESURF_ERROR_INVALID_INPUT);
  linesurf_result_free(result);
}

// The blocks engine through the C API: the mesh of the C++ facade with the same options, and
// (so that the options must have arrived) not the mesh of the default engine.
TEST(CApi, BlocksEngineMatchesTheCppFacade) {
  const CHouse house;
  ASSERT_NE(house.scene, nullptr);
  linesurf_options* options = house.options;
  ASSERT_EQ(linesurf_options_set_string(options, "engine", "blocks", nullptr), LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "block_size", kHouseBlockSize, nullptr),
            LINESURF_OK);
  ASSERT_EQ(linesurf_options_set_number(options, "block_margin", kHouseBlockMargin, nullptr),
            LINESURF_OK);
  ErrorHolder e;
  linesurf_result* result = linesurf_reconstruct(house.scene, options, nullptr, &e.error);
  ASSERT_NE(result, nullptr) << e.Message();

  const auto read = ReadScene(house.path);
  ASSERT_TRUE(read.has_value());
  ReconstructOptions cpp_options;
  cpp_options.scene_mode = SceneMode::kExterior;
  const auto monolithic = Reconstruct(read->scene.View(), cpp_options);
  cpp_options.engine = ComplexEngine::kBlocks;
  cpp_options.block_size = kHouseBlockSize;
  cpp_options.block_margin = kHouseBlockMargin;
  const auto blocks = Reconstruct(read->scene.View(), cpp_options);
  ASSERT_TRUE(monolithic.has_value()) << monolithic.error().ToString();
  ASSERT_TRUE(blocks.has_value()) << blocks.error().ToString();
  EXPECT_EQ(blocks->stats.complex.engine, "blocks");
  EXPECT_GT(blocks->stats.complex.blocks, 1u);
  ExpectSameMesh(result, *blocks);
  EXPECT_NE(blocks->mesh.vertices, monolithic->mesh.vertices);
  linesurf_result_free(result);
}

TEST(CApi, CancelCallbackCancels) {
  const CHouse house;
  ASSERT_NE(house.scene, nullptr);
  linesurf_callbacks callbacks{};
  callbacks.is_cancelled = [](void*) { return 1; };
  ErrorHolder e;
  EXPECT_EQ(linesurf_reconstruct(house.scene, house.options, &callbacks, &e.error), nullptr);
  EXPECT_EQ(linesurf_error_code(e.error), LINESURF_ERROR_CANCELLED) << e.Message();
}

}  // namespace
}  // namespace linesurf
