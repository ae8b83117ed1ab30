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
  EXPECT_STREQ(linesurf_status_name(static_cast<linesurf_status>(99)), "unknown");
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

struct Calls {
  int progress = 0;
  int cancel_polls = 0;
  bool cancel = false;
};

TEST(CApi, HouseMatchesTheCppFacade) {
  const std::string house = testing::ExampleHouseInput().string();
  ErrorHolder e;
  linesurf_scene* scene = linesurf_scene_read(house.c_str(), nullptr, nullptr, &e.error);
  ASSERT_NE(scene, nullptr) << e.Message();
  linesurf_options* options = linesurf_options_create();
  ASSERT_EQ(linesurf_options_set_string(options, "scene_mode", "exterior", &e.error), LINESURF_OK);
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
  linesurf_result* result = linesurf_reconstruct(scene, options, &callbacks, &e.error);
  ASSERT_NE(result, nullptr) << e.Message();
  EXPECT_GT(calls.progress, 0);
  EXPECT_GT(calls.cancel_polls, 0);

  ReconstructOptions cpp_options;
  cpp_options.scene_mode = SceneMode::kExterior;
  const auto read = ReadScene(house);
  ASSERT_TRUE(read.has_value());
  const auto cpp = Reconstruct(read->scene.View(), cpp_options);
  ASSERT_TRUE(cpp.has_value()) << cpp.error().ToString();
  ASSERT_EQ(linesurf_result_num_vertices(result), cpp->mesh.vertices.size());
  ASSERT_EQ(linesurf_result_num_faces(result), cpp->mesh.NumFaces());
  ASSERT_EQ(linesurf_result_num_planes(result), cpp->planes.size());
  const double* v = linesurf_result_vertices(result);
  for (std::size_t i = 0; i < cpp->mesh.vertices.size(); ++i) {
    for (int a = 0; a < 3; ++a) EXPECT_EQ(v[3 * i + a], cpp->mesh.vertices[i][a]);
  }
  const uint32_t* offsets = linesurf_result_face_offsets(result);
  const uint32_t* indices = linesurf_result_face_indices(result);
  EXPECT_EQ(std::vector<uint32_t>(offsets, offsets + cpp->mesh.face_offsets.size()),
            cpp->mesh.face_offsets);
  EXPECT_EQ(std::vector<uint32_t>(indices, indices + cpp->mesh.face_indices.size()),
            cpp->mesh.face_indices);
  EXPECT_EQ(linesurf_result_planes(result)[3], cpp->planes[0].normal[0]);

  const auto dir = testing::FreshTempDir();
  ASSERT_EQ(linesurf_result_write_mesh(result, (dir / "c.ply").c_str(), 0, &e.error), LINESURF_OK)
      << e.Message();
  ASSERT_TRUE(WriteMesh((dir / "cpp.ply").string(), cpp->mesh).has_value());
  EXPECT_TRUE(testing::Slurp(dir / "c.ply") == testing::Slurp(dir / "cpp.ply"));
  EXPECT_EQ(linesurf_result_write_mesh(result, (dir / "m.xyz").c_str(), 0, nullptr),
            LINESURF_ERROR_INVALID_INPUT);

  linesurf_result_free(result);
  linesurf_options_free(options);
  linesurf_scene_free(scene);
}

TEST(CApi, CancelCallbackCancels) {
  const std::string house = testing::ExampleHouseInput().string();
  linesurf_scene* scene = linesurf_scene_read(house.c_str(), nullptr, nullptr, nullptr);
  ASSERT_NE(scene, nullptr);
  linesurf_options* options = linesurf_options_create();
  linesurf_callbacks callbacks{};
  callbacks.is_cancelled = [](void*) { return 1; };
  ErrorHolder e;
  EXPECT_EQ(linesurf_reconstruct(scene, options, &callbacks, &e.error), nullptr);
  EXPECT_EQ(linesurf_error_code(e.error), LINESURF_ERROR_CANCELLED) << e.Message();
  linesurf_options_free(options);
  linesurf_scene_free(scene);
}

}  // namespace
}  // namespace linesurf
