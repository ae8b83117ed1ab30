// host_cpp LINES.json MESH.ply: reconstructs a scene through the installed linesurf library
// with the options of `linesurf reconstruct LINES.json --scene exterior -o MESH.ply`.

#include <cstdio>

#include <linesurf/linesurf.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: host_cpp LINES.json MESH.ply\n");
    return 2;
  }
  linesurf::Expected<linesurf::ReadSceneResult> read = linesurf::ReadScene(argv[1]);
  if (!read) {
    std::fprintf(stderr, "host_cpp: %s\n", read.error().ToString().c_str());
    return 3;
  }

  linesurf::ReconstructOptions options;
  options.scene_mode = linesurf::SceneMode::kExterior;
  linesurf::RunControl control;
  control.on_progress = [](const linesurf::Progress& p) {
    std::fprintf(stderr, "\r%-10s %3.0f %%", p.stage.c_str(), 100.0 * p.stage_fraction);
  };
  linesurf::Expected<linesurf::ReconstructResult> result =
      linesurf::Reconstruct(read->scene.View(), options, control);
  std::fprintf(stderr, "\n");
  if (!result) {
    std::fprintf(stderr,
                 "host_cpp: %s (%s)\n",
                 result.error().ToString().c_str(),
                 linesurf::ErrorCodeName(result.error().code));
    return 4;
  }
  for (const std::string& warning : result->warnings) {
    std::fprintf(stderr, "host_cpp: warning: %s\n", warning.c_str());
  }

  if (linesurf::Status written = linesurf::WriteMesh(argv[2], result->mesh); !written) {
    std::fprintf(stderr, "host_cpp: %s\n", written.error().ToString().c_str());
    return 3;
  }
  const linesurf::ReconstructStats& s = result->stats;
  std::printf("linesurf %s: %zu planes, %zu cells, mesh %zu vertices / %zu faces (%s), %.2f s\n",
              linesurf::LibraryVersion(),
              s.detection.planes,
              s.complex.cells,
              s.surface.mesh_vertices,
              s.surface.mesh_faces,
              s.surface.mesh_closed && s.surface.mesh_manifold ? "closed 2-manifold"
                                                               : "NOT closed",
              s.resources.total_seconds);
  return 0;
}
