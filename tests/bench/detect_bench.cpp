// Plane detection on synthetic cities of growing size (linesurf_bench_detect): time, segments,
// planes and the process's peak resident memory (ru_maxrss, monotonic: run sizes ascending).
// Arguments: number of buildings of `synth city` (about 190 segments each: ~3k, 25k, 240k) and
// the block size of per-block detection in metres (0 = the whole scene at once).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include "engine/detect/detect_planes.h"
#include "tools/gen/synthesize.h"

namespace linesurf {
namespace {

void DetectCity(benchmark::State& state) {
  synth::SynthSpec spec;
  spec.family = "city";
  spec.seed = 1;
  spec.size = static_cast<int>(state.range(0));
  spec.noise_sigma = 0.01;
  spec.outlier_fraction = 0.05;
  Expected<synth::SyntheticScene> city = synth::Synthesize(spec);
  if (!city) {
    state.SkipWithError(city.error().ToString().c_str());
    return;
  }
  PlaneDetectionOptions options;
  options.max_planes = 1000000;  // let the scene decide (min support and failed draws stop)
  options.block_size = static_cast<double>(state.range(1));
  std::size_t planes = 0;
  std::int64_t blocks = 0;
  for (auto _ : state) {
    RunContext ctx;
    Expected<PlaneDetectionResult> r = DetectPlanes(city->scene, options, ctx);
    if (!r) {
      state.SkipWithError(r.error().ToString().c_str());
      return;
    }
    planes = r->planes.size();
    blocks = r->stats.blocks;
    benchmark::DoNotOptimize(r->planes.raw().data());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["segments"] = static_cast<double>(city->scene.segments.size());
  state.counters["planes"] = static_cast<double>(planes);
  state.counters["blocks"] = static_cast<double>(blocks);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(city->scene.segments.size()));
}

// The whole-scene run grows super-linearly (130 buildings: 44 s CPU), so only the small city
// runs it; 30 m blocks match the city's lots.
BENCHMARK(DetectCity)
    ->Args({13, 0})
    ->Args({13, 30})
    ->Args({130, 30})
    ->Args({1300, 30})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace linesurf

BENCHMARK_MAIN();
