// Study of the stitch (docs/user/benchmarks.md, "Studies of one stage"): for a synthetic scene (a `linesurf synth`
// directory: lines.json with the true planes, ground_truth.ply), the block partition at several
// block sizes and margins, cells labelled full when their centroid lies inside the ground truth
// (no solver), then ExtractBlockSurface at 1 and `threads` threads. Prints one Markdown row per
// setting: sizes, times, whether the two meshes are the same bytes, and the checks of
// `linesurf evaluate` (closed, 2-manifold, oriented, self-intersections) with the mesh volume
// against the volume of the full cells.
//   linesurf_stitch_study DIR [threads=2] [sizes=30,15] [margins=1,0]

#include "engine/io/mesh_io.h"
#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/extract_block_surface.h"
#include "partition/arrangement/cell_geometry.h"
#include "tests/bench/study_scene.h"
#include "tests/support/mesh_checks.h"
#include "engine/pipeline/mesh_validity.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace linesurf {
namespace {

std::vector<double> ParseSizes(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stod(item));
  return out;
}

struct Timed {
  pipeline::BlockExtractResult result;
  double seconds = 0.0;
};

Timed StitchTimed(const partition::BlockComplexes& cx,
                  const std::vector<std::uint8_t>& labels,
                  int threads) {
  RunContext ctx;
  ctx.num_threads = threads;
  const auto start = std::chrono::steady_clock::now();
  Expected<pipeline::BlockExtractResult> r = pipeline::ExtractBlockSurface(cx, labels, {}, ctx);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r) {
    std::fprintf(stderr, "%s\n", r.error().ToString().c_str());
    std::exit(1);
  }
  return {std::move(r).value(), seconds};
}

int Run(const std::string& dir,
        int threads,
        const std::vector<double>& sizes,
        const std::vector<double>& margins) {
  const std::optional<Scene> read = ReadStudyScene(dir + "/lines.json");
  Expected<PolygonMesh> truth = io::ReadMesh(dir + "/ground_truth.ply");
  if (!truth) std::fprintf(stderr, "%s\n", truth.error().ToString().c_str());
  if (!read || !truth) return 1;
  const Scene& scene = *read;
  for (Vec3& p : truth->vertices) p = scene.world_from_local.ApplyInverse(p);
  const Box3 box = StudySceneBox(scene);
  std::printf("%zu segments, %zu planes\n\n", scene.segments.size(), scene.planes.size());
  std::printf(
      "| block size | margin | blocks | cells | full | surface faces (seam) | mesh faces | "
      "merged triples | inserted | stitch s, 1 thread | %d threads | same bytes | closed, "
      "manifold, oriented | self-intersecting | volume / full cells |\n",
      threads);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double margin : margins) {
    for (const double size : sizes) {
      pipeline::BlockPartitionOptions options;
      options.block_size = size;
      options.support.margin_blocks = margin;
      Expected<pipeline::BlockPartition> p =
          pipeline::BuildBlockPartition(scene, box, options, RunContext{});
      if (!p) {
        std::fprintf(stderr, "size %g: %s\n", size, p.error().ToString().c_str());
        return 1;
      }
      const partition::BlockComplexes& cx = p->complexes;
      std::vector<Vec3> centroids;
      std::vector<double> volumes;
      for (const partition::BlockComplex& block : cx.blocks) {
        for (std::size_t c = 0; c < block.complex.NumCells(); ++c) {
          centroids.push_back(partition::CellCentroid(block.complex, CellId(c)));
          volumes.push_back(partition::CellVolume(block.complex, CellId(c)));
        }
      }
      const std::vector<bool> inside = testing::PointsStrictlyInside(*truth, centroids);
      std::vector<std::uint8_t> labels(centroids.size(), 0);
      double full_volume = 0.0;
      std::size_t full = 0;
      for (std::size_t c = 0; c < labels.size(); ++c) {
        if (!inside[c]) continue;
        labels[c] = 1;
        full_volume += volumes[c];
        ++full;
      }
      const Timed one = StitchTimed(cx, labels, 1);
      const Timed many = StitchTimed(cx, labels, threads);
      const bool same = one.result.mesh.vertices == many.result.mesh.vertices &&
                        one.result.mesh.face_indices == many.result.mesh.face_indices &&
                        one.result.mesh.face_offsets == many.result.mesh.face_offsets;
      const Expected<MeshValidity> t = CheckMeshValidity(one.result.mesh);
      if (!t) {
        std::fprintf(stderr, "%s\n", t.error().ToString().c_str());
        return 1;
      }
      std::printf(
          "| %.3g | %g | %zu | %zu | %zu | %zu (%zu) | %zu | %zu | %zu | %.2f | %.2f | %s | %s | "
          "%s | %.9f |\n",
          p->stats.block_size,
          options.support.margin_blocks,
          cx.blocks.size(),
          labels.size(),
          full,
          one.result.stats.surface_facets,
          one.result.stitch.seam_surface_facets,
          one.result.mesh.NumFaces(),
          one.result.stitch.merged_vertex_keys,
          one.result.stitch.inserted_vertices,
          one.seconds,
          many.seconds,
          same ? "yes" : "NO",
          t->closed && t->two_manifold && t->oriented ? "yes" : "NO",
          t->self_intersecting ? "YES" : "no",
          full_volume > 0 ? t->signed_volume / full_volume : 0.0);
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace
}  // namespace linesurf

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s DIR [threads=2] [sizes=30,15] [margins=1,0]\n", argv[0]);
    return 2;
  }
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::vector<double> sizes = linesurf::ParseSizes(argc > 3 ? argv[3] : "30,15");
  const std::vector<double> margins = linesurf::ParseSizes(argc > 4 ? argv[4] : "1,0");
  return linesurf::Run(argv[1], threads, sizes, margins);
}
