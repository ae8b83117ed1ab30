// The C API (linesurf/linesurf_c.h) over the C++ facade. Handles are the facade's own structs;
// no exception crosses the extern "C" boundary.

#include "linesurf/linesurf_c.h"

#include "linesurf/linesurf.h"

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

struct linesurf_error {
  linesurf_status code = LINESURF_ERROR_INTERNAL;
  std::string message;
};
struct linesurf_scene {
  linesurf::SceneData data;
};
struct linesurf_options {
  linesurf::ReconstructOptions options;
};
struct linesurf_result {
  linesurf::ReconstructResult result;
  linesurf::ReconstructOptions options;  ///< those of the run, for the report
  std::string report;                    ///< ReportJson, made on the first request
  std::once_flag report_made;
};

namespace {

static_assert(sizeof(linesurf::Vector3) == 3 * sizeof(double), "Vector3 must be 3 packed doubles");
static_assert(sizeof(linesurf::Segment) == 6 * sizeof(double), "Segment must be 6 packed doubles");
static_assert(sizeof(linesurf::Plane) == 6 * sizeof(double), "Plane must be 6 packed doubles");

linesurf_status StatusOf(linesurf::ErrorCode code) {
  return static_cast<linesurf_status>(static_cast<int>(code) + 1);
}

/// Stores a new error in *error (when the host asked for it) and returns its status.
linesurf_status Fail(linesurf_error** error, linesurf_status code, std::string message) noexcept {
  if (error != nullptr) {
    try {
      *error = new linesurf_error{code, std::move(message)};
    } catch (...) {
      *error = nullptr;  // out of memory: the status still tells what happened
    }
  }
  return code;
}

linesurf_status Fail(linesurf_error** error, const linesurf::Error& e) noexcept {
  try {
    return Fail(error, StatusOf(e.code), e.ToString());
  } catch (...) {
    return Fail(error, StatusOf(e.code), std::string());
  }
}

/// Runs `fn` (which reports its own failures through `error`), turning exceptions into errors.
template <typename Fn>
auto Guard(linesurf_error** error, Fn&& fn) noexcept -> decltype(fn()) {
  try {
    return fn();
  } catch (const std::bad_alloc&) {
    Fail(error, LINESURF_ERROR_RESOURCE_EXHAUSTED, "out of memory");
  } catch (const std::exception& e) {
    Fail(error, LINESURF_ERROR_INTERNAL, e.what());
  } catch (...) {
    Fail(error, LINESURF_ERROR_INTERNAL, "unknown exception");
  }
  if constexpr (std::is_same_v<decltype(fn()), linesurf_status>) {
    return LINESURF_ERROR_INTERNAL;
  } else {
    return nullptr;
  }
}

/// Whole numbers of the range of T only.
template <typename T>
bool FitsInteger(double value) {
  return std::isfinite(value) && std::floor(value) == value &&
         value >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
         value <= static_cast<double>(std::numeric_limits<T>::max());
}

/// How setting an option by name went.
enum class SetOutcome { kUnknownName, kWrongKind, kBadValue, kSet };

/// Sets the number option `name` (integers, reals, optional reals, flags as 0/1) of the schema.
SetOutcome SetNumber(linesurf::ReconstructOptions& o, std::string_view name, double value) {
  SetOutcome outcome = SetOutcome::kUnknownName;
  linesurf::VisitOptions(o, [&](const linesurf::OptionSpec& spec, auto& field) {
    if (spec.path != name) return;
    using T = std::remove_reference_t<decltype(field)>;
    if constexpr (std::is_same_v<T, bool>) {
      outcome = value == 0.0 || value == 1.0 ? SetOutcome::kSet : SetOutcome::kBadValue;
      if (outcome == SetOutcome::kSet) field = value != 0.0;
    } else if constexpr (std::is_integral_v<T>) {
      outcome = FitsInteger<T>(value) ? SetOutcome::kSet : SetOutcome::kBadValue;
      if (outcome == SetOutcome::kSet) field = static_cast<T>(value);
    } else if constexpr (std::is_enum_v<T>) {
      outcome = SetOutcome::kWrongKind;
    } else {  // double or std::optional<double>
      field = value;
      outcome = SetOutcome::kSet;
    }
  });
  return outcome;
}

/// Sets the enumerated option `name` of the schema by the name of its value.
SetOutcome SetEnum(linesurf::ReconstructOptions& o, std::string_view name, std::string_view value) {
  SetOutcome outcome = SetOutcome::kUnknownName;
  linesurf::VisitOptions(o, [&](const linesurf::OptionSpec& spec, auto& field) {
    if (spec.path != name) return;
    using T = std::remove_reference_t<decltype(field)>;
    if constexpr (std::is_enum_v<T>) {
      const std::optional<T> parsed = linesurf::OptionEnumFromName<T>(value);
      outcome = parsed ? SetOutcome::kSet : SetOutcome::kBadValue;
      if (parsed) field = *parsed;
    } else {
      outcome = SetOutcome::kWrongKind;
    }
  });
  return outcome;
}

/// The C status and message of a failed SetNumber or SetEnum.
linesurf_status FailSet(linesurf_error** error,
                        SetOutcome outcome,
                        const char* name,
                        const std::string& value,
                        const char* kind) {
  std::string message = "options: ";
  if (outcome == SetOutcome::kUnknownName) {
    message += std::string("no option named '") + name + "'";
  } else if (outcome == SetOutcome::kWrongKind) {
    message += std::string(name) + " is not a " + kind + " option";
  } else {
    message += "'" + value + "' is not a value of " + name;
  }
  return Fail(error, LINESURF_ERROR_INVALID_OPTIONS, message);
}

}  // namespace

extern "C" {

const char* linesurf_version(void) { return linesurf::LibraryVersion(); }

const char* linesurf_status_name(int status) {
  if (status == LINESURF_OK) return "ok";
  if (status < LINESURF_OK || status > LINESURF_ERROR_INTERNAL) return "unknown";
  return linesurf::ErrorCodeName(static_cast<linesurf::ErrorCode>(status - 1));
}

linesurf_status linesurf_error_code(const linesurf_error* error) {
  return error != nullptr ? error->code : LINESURF_OK;
}

const char* linesurf_error_message(const linesurf_error* error) {
  return error != nullptr ? error->message.c_str() : "";
}

void linesurf_error_free(linesurf_error* error) { delete error; }

linesurf_scene* linesurf_scene_read(const char* path,
                                    const char* nvm,
                                    const char* colmap,
                                    linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_scene* {
    if (path == nullptr) {
      Fail(error, LINESURF_ERROR_INVALID_INPUT, "linesurf_scene_read: path is NULL");
      return nullptr;
    }
    linesurf::ReadOptions options;
    if (nvm != nullptr) options.nvm = nvm;
    if (colmap != nullptr) options.colmap = colmap;
    linesurf::Expected<linesurf::ReadSceneResult> read = linesurf::ReadScene(path, options);
    if (!read) {
      Fail(error, read.error());
      return nullptr;
    }
    return new linesurf_scene{std::move(read->scene)};
  });
}

linesurf_scene* linesurf_scene_create(const double* segments,
                                      size_t num_segments,
                                      const double* viewpoints,
                                      size_t num_viewpoints,
                                      const uint32_t* observations,
                                      size_t num_observations,
                                      linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_scene* {
    if ((segments == nullptr && num_segments > 0) ||
        (viewpoints == nullptr && num_viewpoints > 0) ||
        (observations == nullptr && num_observations > 0)) {
      Fail(error,
           LINESURF_ERROR_INVALID_INPUT,
           "linesurf_scene_create: an array with a non-zero length is NULL");
      return nullptr;
    }
    auto scene = std::make_unique<linesurf_scene>();
    linesurf::SceneData& d = scene->data;
    d.segments.resize(num_segments);
    for (size_t i = 0; i < num_segments; ++i) {
      const double* s = segments + 6 * i;
      d.segments[i] = linesurf::Segment{{s[0], s[1], s[2]}, {s[3], s[4], s[5]}};
    }
    d.viewpoints.resize(num_viewpoints);
    for (size_t i = 0; i < num_viewpoints; ++i) {
      const double* v = viewpoints + 3 * i;
      d.viewpoints[i] = {v[0], v[1], v[2]};
    }
    d.observations.resize(num_observations);
    for (size_t i = 0; i < num_observations; ++i) {
      d.observations[i] = linesurf::Observation{observations[2 * i], observations[2 * i + 1]};
    }
    return scene.release();
  });
}

size_t linesurf_scene_num_segments(const linesurf_scene* scene) {
  return scene != nullptr ? scene->data.segments.size() : 0;
}

void linesurf_scene_free(linesurf_scene* scene) { delete scene; }

linesurf_options* linesurf_options_create(void) { return new (std::nothrow) linesurf_options(); }

void linesurf_options_free(linesurf_options* options) { delete options; }

linesurf_status linesurf_options_set_number(linesurf_options* options,
                                            const char* name,
                                            double value,
                                            linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_status {
    if (options == nullptr || name == nullptr) {
      return Fail(error,
                  LINESURF_ERROR_INVALID_OPTIONS,
                  "linesurf_options_set_number: options or name is NULL");
    }
    const SetOutcome outcome = SetNumber(options->options, name, value);
    if (outcome != SetOutcome::kSet) {
      return FailSet(error, outcome, name, std::to_string(value), "numeric");
    }
    return LINESURF_OK;
  });
}

linesurf_status linesurf_options_set_string(linesurf_options* options,
                                            const char* name,
                                            const char* value,
                                            linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_status {
    if (options == nullptr || name == nullptr || value == nullptr) {
      return Fail(error,
                  LINESURF_ERROR_INVALID_OPTIONS,
                  "linesurf_options_set_string: options, name or value is NULL");
    }
    const SetOutcome outcome = SetEnum(options->options, name, value);
    if (outcome != SetOutcome::kSet) return FailSet(error, outcome, name, value, "string");
    return LINESURF_OK;
  });
}

linesurf_result* linesurf_reconstruct(const linesurf_scene* scene,
                                      const linesurf_options* options,
                                      const linesurf_callbacks* callbacks,
                                      linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_result* {
    if (scene == nullptr || options == nullptr) {
      Fail(error, LINESURF_ERROR_INVALID_INPUT, "linesurf_reconstruct: scene or options is NULL");
      return nullptr;
    }
    linesurf::RunControl control;
    if (callbacks != nullptr && callbacks->on_progress != nullptr) {
      control.on_progress = [callbacks](const linesurf::Progress& p) {
        callbacks->on_progress(p.stage.c_str(), p.stage_fraction, callbacks->user_data);
      };
    }
    if (callbacks != nullptr && callbacks->is_cancelled != nullptr) {
      control.is_cancelled = [callbacks] {
        return callbacks->is_cancelled(callbacks->user_data) != 0;
      };
    }
    linesurf::Expected<linesurf::ReconstructResult> r =
        linesurf::Reconstruct(scene->data.View(), options->options, control);
    if (!r) {
      Fail(error, r.error());
      return nullptr;
    }
    auto made = std::make_unique<linesurf_result>();
    made->result = std::move(r.value());
    made->options = options->options;
    return made.release();
  });
}

size_t linesurf_result_num_vertices(const linesurf_result* result) {
  return result != nullptr ? result->result.mesh.vertices.size() : 0;
}

const double* linesurf_result_vertices(const linesurf_result* result) {
  if (result == nullptr || result->result.mesh.vertices.empty()) return nullptr;
  return result->result.mesh.vertices.front().data();
}

size_t linesurf_result_num_faces(const linesurf_result* result) {
  return result != nullptr ? result->result.mesh.NumFaces() : 0;
}

const uint32_t* linesurf_result_face_offsets(const linesurf_result* result) {
  return result != nullptr ? result->result.mesh.face_offsets.data() : nullptr;
}

const uint32_t* linesurf_result_face_indices(const linesurf_result* result) {
  return result != nullptr ? result->result.mesh.face_indices.data() : nullptr;
}

size_t linesurf_result_num_planes(const linesurf_result* result) {
  return result != nullptr ? result->result.planes.size() : 0;
}

const double* linesurf_result_planes(const linesurf_result* result) {
  if (result == nullptr || result->result.planes.empty()) return nullptr;
  return result->result.planes.front().point.data();
}

size_t linesurf_result_num_warnings(const linesurf_result* result) {
  return result != nullptr ? result->result.warnings.size() : 0;
}

const char* linesurf_result_warning(const linesurf_result* result, size_t index) {
  if (result == nullptr || index >= result->result.warnings.size()) return "";
  return result->result.warnings[index].c_str();
}

const char* linesurf_result_report_json(const linesurf_result* result, linesurf_error** error) {
  return Guard(error, [&]() -> const char* {
    if (result == nullptr) {
      Fail(error, LINESURF_ERROR_INVALID_INPUT, "linesurf_result_report_json: result is NULL");
      return nullptr;
    }
    auto& r = const_cast<linesurf_result&>(*result);  // the report is made once, then read
    std::call_once(r.report_made, [&r] { r.report = linesurf::ReportJson(r.result, r.options); });
    return r.report.c_str();
  });
}

linesurf_status linesurf_result_write_mesh(const linesurf_result* result,
                                           const char* path,
                                           int ascii,
                                           linesurf_error** error) {
  return Guard(error, [&]() -> linesurf_status {
    if (result == nullptr || path == nullptr) {
      return Fail(error,
                  LINESURF_ERROR_INVALID_INPUT,
                  "linesurf_result_write_mesh: result or path is NULL");
    }
    linesurf::MeshWriteOptions options;
    options.ascii = ascii != 0;
    const linesurf::Status s = linesurf::WriteMesh(path, result->result.mesh, options);
    return s ? LINESURF_OK : Fail(error, s.error());
  });
}

void linesurf_result_free(linesurf_result* result) { delete result; }

}  // extern "C"
