#include "engine/pipeline/evaluate_mesh.h"

#include "linesurf/options.h"

#include "engine/core/coordinate_bound.h"
#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/pipeline/mesh_validity.h"
#include "partition/mesh/triangle_tree.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace linesurf::pipeline {
namespace {

constexpr const char* kEvaluateMeshStage = "evaluate_mesh";
/// More samples than this take gigabytes and give shares no steadier than +-0.01 %.
constexpr std::size_t kMaxSamplesPerMesh = 10000000;
/// Samples per parallel task; fixed so chunking never depends on the thread count.
constexpr std::size_t kSampleGrain = 1024;
/// Stream tags of the two sample sets.
constexpr std::uint64_t kResultStream = 1;
constexpr std::uint64_t kGroundTruthStream = 2;

/// A mesh's triangle tree with cumulative triangle areas for area-uniform sampling.
struct TriangleSet {
  partition::TriangleTree tree;
  std::vector<double> cumulative_area;  ///< cumulative_area[t] = area of triangles 0..t
  [[nodiscard]] double Area() const { return cumulative_area.empty() ? 0.0 : cumulative_area.back(); }
};

TriangleSet Triangulate(const PolygonMesh& mesh, const std::string& name) {
  TriangleSet set{partition::TriangleTree(mesh, kEvaluateMeshStage, name), {}};
  double total = 0.0;
  for (std::size_t t = 0; t < set.tree.NumTriangles(); ++t) {
    total += set.tree.Area(t);
    set.cumulative_area.push_back(total);
  }
  return set;
}

/// Sample i of a stream: an area-uniform triangle, then uniform barycentrics
/// (1 - sqrt r1, sqrt r1 (1 - r2), sqrt r1 r2).
Vec3 SamplePoint(const TriangleSet& set, std::uint64_t seed, std::uint64_t stream, std::size_t i) {
  Rng rng(MixSeed(seed, RngStage::kEvaluate, stream, i));
  const double u = rng.Uniform() * set.Area();
  const auto it = std::upper_bound(set.cumulative_area.begin(), set.cumulative_area.end(), u);
  const std::size_t t = std::min<std::size_t>(
      static_cast<std::size_t>(it - set.cumulative_area.begin()), set.tree.NumTriangles() - 1);
  const double s1 = std::sqrt(rng.Uniform());
  const double r2 = rng.Uniform();
  const auto [p0, p1, p2] = set.tree.Corners(t);
  return (1.0 - s1) * p0 + (s1 * (1.0 - r2)) * p1 + (s1 * r2) * p2;
}

template <typename Fn>
void ForEachChunk(std::size_t n, const RunContext* ctx, Fn&& fn) {
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, kSampleGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (ctx != nullptr && ctx->ShouldStop()) return;
        fn(r.begin(), r.end());
      },
      tbb::simple_partitioner{});
  if (ctx != nullptr) ctx->ThrowIfCancelled(kEvaluateMeshStage);
}

DistanceStats Summarise(std::vector<double> distances) {
  DistanceStats stats;
  stats.count = distances.size();
  if (distances.empty()) return stats;
  std::sort(distances.begin(), distances.end());
  double sum = 0.0;
  for (double d : distances) sum += d;  // serial, sorted order: deterministic
  const auto at = [&](double q) {
    return distances[static_cast<std::size_t>(std::floor(q * static_cast<double>(distances.size() - 1)))];
  };
  stats.mean = sum / static_cast<double>(distances.size());
  stats.median = at(0.5);
  stats.p95 = at(0.95);
  stats.max = distances.back();
  return stats;
}

std::vector<double> SharesUnder(const std::vector<double>& distances,
                                const std::vector<double>& thresholds) {
  std::vector<double> shares;
  for (double thr : thresholds) {
    const auto under = std::count_if(distances.begin(), distances.end(),
                                     [thr](double d) { return d <= thr; });
    shares.push_back(distances.empty() ? 0.0
                                       : static_cast<double>(under) /
                                             static_cast<double>(distances.size()));
  }
  return shares;
}

EvaluationResult Evaluate(const PolygonMesh& result_mesh, const PolygonMesh& gt_mesh,
                          const EvaluationOptions& options,
                          const std::optional<std::vector<Vec3>>& visible_from,
                          const RunContext* ctx) {
  const TriangleSet result_set = Triangulate(result_mesh, "result");
  const TriangleSet gt_set = Triangulate(gt_mesh, "ground truth");

  const std::size_t n = options.samples_per_mesh;
  std::vector<double> result_to_gt(n);
  ForEachChunk(n, ctx, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 p = SamplePoint(result_set, options.seed, kResultStream, i);
      result_to_gt[i] = std::sqrt(gt_set.tree.SquaredDistance(p));
    }
  });

  // NaN marks a ground-truth sample that no viewpoint sees.
  std::vector<double> gt_to_result(n);
  ForEachChunk(n, ctx, [&](std::size_t begin, std::size_t end) {
    std::size_t last_seen_by = 0;  // try the last successful viewpoint first (speed only)
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 p = SamplePoint(gt_set, options.seed, kGroundTruthStream, i);
      bool visible = !visible_from.has_value();
      if (!visible) {
        const std::vector<Vec3>& views = *visible_from;
        for (std::size_t k = 0; k < views.size() && !visible; ++k) {
          const std::size_t v = (last_seen_by + k) % views.size();
          const Vec3 ray = p - views[v];
          const double length = ray.norm();
          if (length <= options.visibility_offset) {
            visible = true;
          } else {
            const Vec3 stop = p - ray * (options.visibility_offset / length);
            visible = !gt_set.tree.Intersects(views[v], stop);
          }
          if (visible) last_seen_by = v;
        }
      }
      gt_to_result[i] = visible ? std::sqrt(result_set.tree.SquaredDistance(p))
                                : std::nan("");
    }
  });
  std::erase_if(gt_to_result, [](double d) { return std::isnan(d); });

  EvaluationResult out;
  out.thresholds = options.thresholds;
  out.precision = SharesUnder(result_to_gt, options.thresholds);
  out.completeness = SharesUnder(gt_to_result, options.thresholds);
  out.num_gt_samples = n;
  out.num_visible_gt_samples = gt_to_result.size();
  out.result_to_gt = Summarise(std::move(result_to_gt));
  out.gt_to_result = Summarise(std::move(gt_to_result));
  out.result_area = result_set.Area();
  out.gt_area = gt_set.Area();
  auto topology = CheckMeshValidity(result_mesh);
  if (!topology) throw LinesurfException(topology.error());
  out.topology = *topology;
  return out;
}

}  // namespace

Status ValidateEvaluationOptions(const EvaluationOptions& options) noexcept {
  constexpr const char* kStage = "evaluation_options";
  return CatchAll(kStage, [&] {
    const std::vector<double>& t = options.thresholds;
    LINESURF_THROW_IF(t.empty(), kInvalidOptions, kStage, "thresholds must not be empty");
    for (std::size_t i = 0; i < t.size(); ++i) {
      LINESURF_THROW_IF(!(t[i] > 0.0) || !std::isfinite(t[i]), kInvalidOptions, kStage,
                        "threshold " << t[i] << " must be > 0");
      LINESURF_THROW_IF(i > 0 && !(t[i] > t[i - 1]), kInvalidOptions, kStage,
                        "thresholds must be increasing");
    }
    LINESURF_THROW_IF(options.samples_per_mesh < 1 || options.samples_per_mesh > kMaxSamplesPerMesh,
                      kInvalidOptions, kStage,
                      "samples_per_mesh must be in [1, " << kMaxSamplesPerMesh << "]");
    LINESURF_THROW_IF(!(options.visibility_offset > 0.0) || !std::isfinite(options.visibility_offset),
                      kInvalidOptions, kStage, "visibility_offset must be > 0");
    LINESURF_THROW_IF(options.num_threads < 0 || options.num_threads > kMaxThreads,
                      kInvalidOptions, kStage, "num_threads must be in [0, " << kMaxThreads << "]");
  });
}

Expected<EvaluationResult> EvaluateMesh(const PolygonMesh& result, const PolygonMesh& ground_truth,
                                        const EvaluationOptions& options,
                                        const std::optional<std::vector<Vec3>>& visible_from,
                                        const RunContext* ctx) noexcept {
  if (auto valid = ValidateEvaluationOptions(options); !valid) return valid.error();
  // Beyond the coordinate bound the exact fallback of CGAL meets overflowed doubles (GMP raises
  // SIGFPE on converting inf): refuse such meshes before any geometry.
  for (const auto& [mesh, name] :
       {std::pair{&result, "result"}, std::pair{&ground_truth, "ground truth"}}) {
    if (const auto violation = CoordinateBoundViolation(*mesh)) {
      return Error{
          ErrorCode::kInvalidInput, kEvaluateMeshStage, std::string(name) + " mesh: " + *violation};
    }
  }
  return CatchAll(kEvaluateMeshStage, [&] {
    if (ctx == nullptr) return Evaluate(result, ground_truth, options, visible_from, ctx);
    return RunInArena(*ctx, [&] { return Evaluate(result, ground_truth, options, visible_from, ctx); });
  });
}

}  // namespace linesurf::pipeline
