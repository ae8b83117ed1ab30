// Reference JSON read/write throughput on generated scenes (docs/user/formats.md has the 100 MB
// measurement against a DOM parse). Run: build/bin/linesurf_bench_io --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true (repetitions + median against machine noise).

#include <benchmark/benchmark.h>

#include <filesystem>

#include "engine/core/rng.h"
#include "engine/io/reference_json.h"

namespace linesurf::io {
namespace {

/// `n` random segments with 3 views each out of 200 viewpoints, every 2nd on one plane.
Scene RandomScene(std::size_t n) {
  Rng rng(Mix64(n));
  Scene scene;
  for (int v = 0; v < 200; ++v) {
    scene.viewpoints.push_back(
        Vec3(rng.Uniform(-50, 50), rng.Uniform(-50, 50), rng.Uniform(0, 20)));
  }
  scene.planes.push_back(Plane3{Vec3::Zero(), Vec3::UnitZ()});
  for (std::size_t s = 0; s < n; ++s) {
    const Vec3 a(rng.Uniform(-20, 20), rng.Uniform(-20, 20), rng.Uniform(0, 10));
    scene.segments.push_back(Segment3{a, a + Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), 0.5)});
    std::vector<ViewpointId> row;
    for (int k = 0; k < 3; ++k) {
      row.push_back(ViewpointId(static_cast<std::size_t>(rng.Below(200))));
    }
    scene.observations.AddRow(row);
    PlaneMembership m;
    if (s % 2 == 0) m.Add(PlaneId(0u));
    scene.memberships.push_back(m);
  }
  return scene;
}

std::filesystem::path BenchFile(std::size_t n) {
  return std::filesystem::temp_directory_path() /
         ("linesurf_io_bench_" + std::to_string(n) + ".json");
}

void BM_ReadReferenceJson(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto path = BenchFile(n);
  if (!WriteReferenceJson(RandomScene(n), path)) state.SkipWithError("cannot write the input");
  for (auto _ : state) {
    auto scene = ReadReferenceJson(path);
    benchmark::DoNotOptimize(scene);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() *
                          static_cast<std::int64_t>(std::filesystem::file_size(path)));
  std::filesystem::remove(path);
}
BENCHMARK(BM_ReadReferenceJson)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_WriteReferenceJson(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Scene scene = RandomScene(n);
  const auto path = BenchFile(n);
  for (auto _ : state) {
    const Status status = WriteReferenceJson(scene, path);
    benchmark::DoNotOptimize(status);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  std::filesystem::remove(path);
}
BENCHMARK(BM_WriteReferenceJson)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linesurf::io

BENCHMARK_MAIN();
