// Build time of the exact cell complex (linesurf_bench_arrangement): random planes and
// building-like planes (mostly axis-aligned) in the box [-1, 1]^3. Counters: cells, facets,
// vertices, exact predicate fallbacks and the process's peak resident memory so far (the cases
// run from small to large, so it approximates each case's peak).

#include <sys/resource.h>

#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/core/rng.h"
#include "partition/arrangement/build_cell_complex.h"

namespace linesurf::partition {
namespace {

enum class PlaneFamily { kRandom, kBuilding };

/// n planes crossing [-1, 1]^3. Building-like: 85% axis-aligned (walls in x and y, floors in z)
/// at random offsets, 15% roof-like planes tilted 20-45 degrees about a horizontal axis.
std::vector<Plane3> MakePlanes(PlaneFamily family, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Plane3> planes;
  for (std::size_t i = 0; i < n; ++i) {
    Plane3 p;
    p.point = Vec3(rng.Uniform(-0.95, 0.95), rng.Uniform(-0.95, 0.95), rng.Uniform(-0.95, 0.95));
    if (family == PlaneFamily::kRandom) {
      p.normal = Vec3(rng.Normal(), rng.Normal(), rng.Normal()).normalized();
    } else if (rng.Uniform() < 0.85) {
      const double u = rng.Uniform();
      p.normal = u < 0.4 ? Vec3::UnitX() : (u < 0.8 ? Vec3::UnitY() : Vec3::UnitZ());
    } else {
      const double slope = rng.Uniform(20.0, 45.0) * 3.14159265358979 / 180.0;
      const bool about_x = rng.Uniform() < 0.5;
      p.normal = about_x ? Vec3(0, std::sin(slope), std::cos(slope)) : Vec3(std::sin(slope), 0, std::cos(slope));
    }
    planes.push_back(p);
  }
  return planes;
}

double PeakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void BM_BuildCellComplex(benchmark::State& state, PlaneFamily family) {
  const auto planes = MakePlanes(family, static_cast<std::size_t>(state.range(0)), 2024);
  Box3 box;
  box.min = Vec3::Constant(-1);
  box.max = Vec3::Constant(1);
  const RunContext ctx;
  std::size_t cells = 0, facets = 0, vertices = 0;
  std::uint64_t fallbacks = 0;
  for (auto _ : state) {
    auto result = BuildCellComplex(box, planes, {}, ctx);
    if (!result) {
      state.SkipWithError(result.error().ToString().c_str());
      return;
    }
    cells = result->complex.NumCells();
    facets = result->complex.NumFacets();
    vertices = result->complex.NumVertices();
    fallbacks = result->stats.exact_fallbacks;
    benchmark::DoNotOptimize(result->complex.cell_facets.items().data());
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["facets"] = static_cast<double>(facets);
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["exact_fallbacks"] = static_cast<double>(fallbacks);
  state.counters["peak_rss_mb"] = PeakRssMb();
}

void BM_Random(benchmark::State& state) { BM_BuildCellComplex(state, PlaneFamily::kRandom); }
void BM_Building(benchmark::State& state) { BM_BuildCellComplex(state, PlaneFamily::kBuilding); }

BENCHMARK(BM_Building)->Arg(10)->Arg(40)->Arg(100)->Arg(150)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Random)->Arg(10)->Arg(40)->Arg(100)->Arg(150)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace linesurf::partition

BENCHMARK_MAIN();
