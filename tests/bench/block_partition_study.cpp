// Study of the block partition (docs/user/benchmarks.md, "Studies of one stage"): for a scene with planes
// and memberships (reference JSON with plane_index, or a synthetic scene's lines.json), the
// monolithic complex of the scene box against the block complexes at several block sizes and
// support margins. Prints one Markdown row per setting.
//   linesurf_block_study PATH [validate=0|1] [threads=0] [sizes=0,40,20,10] [margins=1]
//                        [monolithic=1]
// Size 0 is the automatic rule. The scene box is the box of the segments and viewpoints grown
// by 5 % of each extent (the reconstruct default box_margin) on every side.

#include "engine/pipeline/block_partition.h"
#include "engine/pipeline/stage_timer.h"
#include "partition/arrangement/block_complexes.h"
#include "tests/bench/study_scene.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace linesurf {
namespace {

std::vector<double> ParseList(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

/// User + system CPU seconds of the process so far (all threads).
double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int Run(const std::string& path,
        bool validate,
        int threads,
        const std::vector<double>& sizes,
        const std::vector<double>& margins,
        bool monolithic) {
  const std::optional<Scene> read = ReadStudyScene(path);
  if (!read) return 1;
  const Scene& scene = *read;
  RunContext ctx;
  ctx.num_threads = threads;
  const Box3 box = StudySceneBox(scene);
  std::printf("%zu segments, %zu planes, box extent %.1f x %.1f x %.1f\n\n",
              scene.segments.size(),
              scene.planes.size(),
              box.Extent().x(),
              box.Extent().y(),
              box.Extent().z());
  std::printf(
      "| block size | margin | blocks | plane-block pairs | cells | seam facets | "
      "planes on faces | complexes s | overlay s | CPU s | valid | peak RSS MB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  if (monolithic) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu = CpuSeconds();
    Expected<partition::CellComplexResult> mono =
        partition::BuildCellComplex(box, scene.planes.raw(), {}, ctx);
    if (!mono) {
      std::fprintf(stderr, "%s\n", mono.error().ToString().c_str());
      return 1;
    }
    std::printf("| monolithic | - | 1 | %zu | %zu | - | - | %.2f | - | %.2f | - | %.0f |\n",
                mono->stats.planes_used,
                mono->complex.NumCells(),
                Seconds(start),
                CpuSeconds() - cpu,
                static_cast<double>(PeakRssBytes()) / 1e6);
    std::fflush(stdout);
  }
  for (const double margin : margins) {
    for (const double size : sizes) {
      pipeline::BlockPartitionOptions options;
      options.block_size = size;
      options.support.margin_blocks = margin;
      const double cpu = CpuSeconds();
      Expected<pipeline::BlockPartition> p =
          pipeline::BuildBlockPartition(scene, box, options, ctx);
      const double cpu_seconds = CpuSeconds() - cpu;
      if (!p) {
        std::fprintf(stderr, "size %g: %s\n", size, p.error().ToString().c_str());
        return 1;
      }
      const partition::BlockComplexesStats& s = p->complexes.stats;
      const char* valid = "-";
      if (validate) valid = partition::ValidateBlockComplexes(p->complexes) ? "yes" : "NO";
      std::printf(
          "| %.3g%s | %g | %zu | %zu | %zu | %zu | %zu | %.2f | %.2f | %.2f | %s | %.0f |\n",
          p->stats.block_size,
          p->stats.automatic_size ? " (auto)" : "",
          options.support.margin_blocks,
          s.blocks,
          s.plane_block_pairs,
          s.cells,
          s.seam_facets,
          s.planes_on_faces,
          s.seconds_complexes,
          s.seconds_overlay,
          cpu_seconds,
          valid,
          static_cast<double>(PeakRssBytes()) / 1e6);
      std::fflush(stdout);  // one row at a time: settings can take minutes
    }
  }
  return 0;
}

}  // namespace
}  // namespace linesurf

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: %s PATH [validate=0|1] [threads=0] [sizes=0,40,20,10] [margins=1] "
                 "[monolithic=1]\n",
                 argv[0]);
    return 2;
  }
  const bool validate = argc > 2 && std::atoi(argv[2]) != 0;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 0;
  const std::vector<double> sizes = linesurf::ParseList(argc > 4 ? argv[4] : "0,40,20,10");
  const std::vector<double> margins = linesurf::ParseList(argc > 5 ? argv[5] : "1");
  const bool monolithic = argc <= 6 || std::atoi(argv[6]) != 0;
  return linesurf::Run(argv[1], validate, threads, sizes, margins, monolithic);
}
