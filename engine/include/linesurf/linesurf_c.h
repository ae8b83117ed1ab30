#ifndef LINESURF_LINESURF_C_H_
#define LINESURF_LINESURF_C_H_
/* @file linesurf_c.h
 * @brief The C API of linesurf, for hosts in other languages (C# BIM plug-ins, ...): opaque
 * handles, status codes and error objects, over the C++ facade (linesurf.h) in the same shared
 * library. No C++ types; every function is safe to call with the documented NULL arguments and
 * never aborts or prints.
 *
 * Errors: a function that can fail takes `linesurf_error** error` as its last argument. On
 * failure it returns NULL (or a non-zero status) and, when `error` is not NULL, stores a new
 * error object there that the caller frees with linesurf_error_free. On success *error is left
 * untouched.
 *
 * Coordinates are doubles in scene units (metres for metric scenes); arrays are flat: a segment is
 * 6 doubles (x1 y1 z1 x2 y2 z2), a point 3, a plane 6 (point xyz, unit normal xyz), an
 * observation 2 uint32 (segment index, viewpoint index).
 *
 * @code
 *   linesurf_error* error = NULL;
 *   linesurf_scene* scene = linesurf_scene_read("lines.json", NULL, NULL, &error);
 *   linesurf_options* options = linesurf_options_create();
 *   linesurf_options_set_string(options, "scene_mode", "exterior", &error);
 *   linesurf_result* result = linesurf_reconstruct(scene, options, NULL, &error);
 *   if (result) linesurf_result_write_mesh(result, "house.ply", 0, &error);
 *   if (error) { fprintf(stderr, "%s\n", linesurf_error_message(error));
 * linesurf_error_free(error); } linesurf_result_free(result); linesurf_options_free(options);
 * linesurf_scene_free(scene);
 * @endcode
 */

#include "linesurf/export.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes; the same order as linesurf::ErrorCode, shifted by one (0 = success). */
typedef enum linesurf_status {
  LINESURF_OK = 0,
  LINESURF_ERROR_INVALID_OPTIONS = 1,
  LINESURF_ERROR_INVALID_INPUT = 2,
  LINESURF_ERROR_DEGENERATE = 3,
  LINESURF_ERROR_CANCELLED = 4,
  LINESURF_ERROR_SOLVER_FAILED = 5,
  LINESURF_ERROR_RESOURCE_EXHAUSTED = 6,
  LINESURF_ERROR_INTERNAL = 7
} linesurf_status;

typedef struct linesurf_error linesurf_error;
typedef struct linesurf_scene linesurf_scene;
typedef struct linesurf_options linesurf_options;
typedef struct linesurf_result linesurf_result;

/* Progress and cancel callbacks of a run; any member may be NULL. Never called concurrently. */
typedef struct linesurf_callbacks {
  /* stage ("detect_planes", "cell_complex", "evidence", "solve_labeling", ...) and its completed
   * fraction in [0, 1]. */
  void (*on_progress)(const char* stage, double fraction, void* user_data);
  /* Non-zero stops the run with LINESURF_ERROR_CANCELLED. Keep it cheap. */
  int (*is_cancelled)(void* user_data);
  void* user_data;
} linesurf_callbacks;

/* The library version, e.g. "3.0.0". */
LINESURF_API const char* linesurf_version(void);
/* "ok", "invalid_options", "invalid_input", ...; "unknown" for an int that is no linesurf_status
 * (an int, not the enum, because such a value held in the enum type is undefined in C++). */
LINESURF_API const char* linesurf_status_name(int status);

LINESURF_API linesurf_status linesurf_error_code(const linesurf_error* error);
/* "stage: message", naming the offending file, line, index or field. Valid until freed. */
LINESURF_API const char* linesurf_error_message(const linesurf_error* error);
LINESURF_API void linesurf_error_free(linesurf_error* error);

/* Reads a scene file (reference JSON, Line3D++ .txt with `nvm` or `colmap`, OBJ lines); `nvm`
 * and `colmap` may be NULL. */
LINESURF_API linesurf_scene* linesurf_scene_read(const char* path,
                                                 const char* nvm,
                                                 const char* colmap,
                                                 linesurf_error** error);
/* A scene copied from flat arrays (see the file comment); arrays of zero length may be NULL.
 * Indices are checked by linesurf_reconstruct. */
LINESURF_API linesurf_scene* linesurf_scene_create(const double* segments,
                                                   size_t num_segments,
                                                   const double* viewpoints,
                                                   size_t num_viewpoints,
                                                   const uint32_t* observations,
                                                   size_t num_observations,
                                                   linesurf_error** error);
LINESURF_API size_t linesurf_scene_num_segments(const linesurf_scene* scene);
LINESURF_API void linesurf_scene_free(linesurf_scene* scene);

/* Reconstruction options with the defaults of linesurf::ReconstructOptions. */
LINESURF_API linesurf_options* linesurf_options_create(void);
LINESURF_API void linesurf_options_free(linesurf_options* options);
/* Sets a numeric option by its path in linesurf/option_schema.h (the C++ field path), e.g.
 * "weights.visibility", "detection.epsilon", "sigma", "seed", "num_threads", "triangulate",
 * "merge_coplanar" (0/1). Unknown names, enumerated options and values that do not fit the field
 * give LINESURF_ERROR_INVALID_OPTIONS; ranges are checked by linesurf_reconstruct. */
LINESURF_API linesurf_status linesurf_options_set_number(linesurf_options* options,
                                                         const char* name,
                                                         double value,
                                                         linesurf_error** error);
/* Sets an enumerated option by name: "plane_source" (detect, given), "scene_mode" (exterior,
 * interior, auto), "solver.backend" (auto, clp, maxflow, pdhg, band, cbc, clp-barrier, blocks,
 * pdhg-energy), "engine" (monolithic, blocks). */
LINESURF_API linesurf_status linesurf_options_set_string(linesurf_options* options,
                                                         const char* name,
                                                         const char* value,
                                                         linesurf_error** error);

/* The whole method (linesurf::Reconstruct). `callbacks` may be NULL. */
LINESURF_API linesurf_result* linesurf_reconstruct(const linesurf_scene* scene,
                                                   const linesurf_options* options,
                                                   const linesurf_callbacks* callbacks,
                                                   linesurf_error** error);
LINESURF_API size_t linesurf_result_num_vertices(const linesurf_result* result);
/* 3 doubles per vertex, world coordinates; valid until the result is freed. */
LINESURF_API const double* linesurf_result_vertices(const linesurf_result* result);
LINESURF_API size_t linesurf_result_num_faces(const linesurf_result* result);
/* num_faces + 1 offsets into the face indices (face f = indices[offsets[f] .. offsets[f+1])). */
LINESURF_API const uint32_t* linesurf_result_face_offsets(const linesurf_result* result);
LINESURF_API const uint32_t* linesurf_result_face_indices(const linesurf_result* result);
LINESURF_API size_t linesurf_result_num_planes(const linesurf_result* result);
/* 6 doubles per plane: a point on it, then its unit normal. */
LINESURF_API const double* linesurf_result_planes(const linesurf_result* result);
LINESURF_API size_t linesurf_result_num_warnings(const linesurf_result* result);
LINESURF_API const char* linesurf_result_warning(const linesurf_result* result, size_t index);
/* The run report as JSON text (linesurf/report.h: the layout of `linesurf reconstruct --report`
 * without its paths), valid until the result is freed; NULL with *error set when it cannot be
 * made (out of memory). */
LINESURF_API const char* linesurf_result_report_json(const linesurf_result* result,
                                                    linesurf_error** error);
/* Writes the mesh as PLY (binary, or ASCII when `ascii` is non-zero), OBJ or OFF by extension:
 * the same bytes as `linesurf reconstruct -o`. */
LINESURF_API linesurf_status linesurf_result_write_mesh(const linesurf_result* result,
                                                        const char* path,
                                                        int ascii,
                                                        linesurf_error** error);
LINESURF_API void linesurf_result_free(linesurf_result* result);

#ifdef __cplusplus
}
#endif

#endif /* LINESURF_LINESURF_C_H_ */
