/* host_c LINES.json MESH.ply: reconstructs a scene through the C API of the installed linesurf
 * library, with the options of `linesurf reconstruct LINES.json --scene exterior -o MESH.ply`. */

#include <linesurf/linesurf_c.h>
#include <stdio.h>

static void on_progress(const char* stage, double fraction, void* user_data) {
  (void)user_data;
  fprintf(stderr, "\r%-10s %3.0f %%", stage, 100.0 * fraction);
}

static int fail(linesurf_error* error, int exit_code) {
  fprintf(stderr,
          "\nhost_c: %s (%s)\n",
          linesurf_error_message(error),
          linesurf_status_name(linesurf_error_code(error)));
  linesurf_error_free(error);
  return exit_code;
}

int main(int argc, char** argv) {
  linesurf_error* error = NULL;
  linesurf_scene* scene = NULL;
  linesurf_options* options = NULL;
  linesurf_result* result = NULL;
  linesurf_callbacks callbacks = {on_progress, NULL, NULL};
  int exit_code = 0;

  if (argc != 3) {
    fprintf(stderr, "usage: host_c LINES.json MESH.ply\n");
    return 2;
  }
  scene = linesurf_scene_read(argv[1], NULL, NULL, &error);
  if (scene == NULL) return fail(error, 3);

  options = linesurf_options_create();
  if (options == NULL ||
      linesurf_options_set_string(options, "scene_mode", "exterior", &error) != LINESURF_OK) {
    exit_code = error ? fail(error, 2) : 70;
    goto done;
  }
  result = linesurf_reconstruct(scene, options, &callbacks, &error);
  fprintf(stderr, "\n");
  if (result == NULL) {
    exit_code = fail(error, 4);
    goto done;
  }
  if (linesurf_result_write_mesh(result, argv[2], 0, &error) != LINESURF_OK) {
    exit_code = fail(error, 3);
    goto done;
  }
  printf("linesurf %s: %zu planes, mesh %zu vertices / %zu faces\n",
         linesurf_version(),
         linesurf_result_num_planes(result),
         linesurf_result_num_vertices(result),
         linesurf_result_num_faces(result));

done:
  linesurf_result_free(result);
  linesurf_options_free(options);
  linesurf_scene_free(scene);
  return exit_code;
}
