// Studies of docs/design/plane_detection.md, printed as Markdown tables:
//   linesurf_detect_study robustness [exhaustive_max=64] [noise_model=ball|gauss] [trials=20]
//                                    [face=held|near]
//       The paper's robustness toy: the 12 edges of a cube of side 2 (linesurf_synth "cube"),
//       endpoint noise 0..0.35, 0..50 outliers in a ball of radius 2, eps 0.06, N_iter 100; mean
//       number of faces found (held: one plane holds its 4 edges; near: a plane within 5 degrees
//       and 2 eps of the face), full method and both ablations.
//   linesurf_detect_study edge-tests [samples=200000]
//       Why the robustness goal is out of reach: the probability that one noisy cube edge passes
//       the textural and the crease tests against the true geometry, per noise level.
//   linesurf_detect_study andalusian PATH [threads=0]
//       Detection on the Andalusian segments ignoring the given planes (eps 0.02, N_max 160) and
//       how many of the reference planes are matched (angle < 5 deg, the reference plane's
//       inliers within 3 eps of ours).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "engine/core/rng.h"
#include "engine/detect/collinear_groups.h"
#include "engine/detect/detect_planes.h"
#include "engine/detect/segment_geometry.h"
#include "engine/io/reference_json.h"
#include "engine/pipeline/sanitize_scene.h"
#include "tools/eval/evaluate_planes.h"
#include "tools/gen/synthesize.h"

namespace linesurf {
namespace {

/// `near`: a face counts when a detected plane is within 5 degrees and 2 eps of it (instead of
/// holding its 4 edges).
int Robustness(int exhaustive_max, synth::NoiseModel model, int trials, bool near) {
  const std::vector<double> noises = {0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35};
  const std::vector<int> outliers = {0, 10, 20, 30, 40, 50};
  const char* variants[] = {"full", "single_support", "no_structural_condition"};
  for (int variant = 0; variant < 3; ++variant) {
    std::printf("\n%s (exhaustive pairs up to %d segments, noise %s, %d trials, face %s)\n\n"
                "| noise \\ outliers |",
                variants[variant], exhaustive_max,
                model == synth::NoiseModel::kUniformBall ? "uniform in ball" : "gaussian", trials,
                near ? "= a plane within 5 deg and 2 eps" : "= one plane holds its 4 edges");
    for (int o : outliers) std::printf(" %d |", o);
    std::printf("\n|---|");
    for (std::size_t i = 0; i < outliers.size(); ++i) std::printf("---|");
    std::printf("\n");
    for (double noise : noises) {
      std::printf("| %.2f |", noise);
      for (int o : outliers) {
        int total = 0;
        for (int t = 0; t < trials; ++t) {
          synth::SynthSpec spec;
          spec.family = "cube";
          spec.seed = static_cast<std::uint64_t>(1000 + t);
          spec.noise_sigma = noise;
          spec.noise_model = model;
          spec.outlier_count = o;
          Expected<synth::SyntheticScene> cube = synth::Synthesize(spec);
          if (!cube) {
            std::fprintf(stderr, "%s\n", cube.error().ToString().c_str());
            return 1;
          }
          PlaneDetectionOptions options;
          options.epsilon = 0.06;
          options.iterations = 100;
          options.exhaustive_pairs_max_segments = exhaustive_max;
          options.seed = static_cast<std::uint64_t>(t);
          options.single_support = variant == 1;
          options.no_structural_condition = variant == 2;
          RunContext ctx;
          ctx.num_threads = 1;
          Expected<PlaneDetectionResult> r = DetectPlanes(cube->scene, options, ctx);
          if (!r) {
            std::fprintf(stderr, "%s\n", r.error().ToString().c_str());
            return 1;
          }
          total += near ? eval::EvaluatePlaneRecovery(cube->scene, r->planes, 5.0,
                                                      2.0 * r->stats.epsilon, 1)
                              .found
                        : eval::CountTruePlanesHeld(cube->scene, r->memberships);
        }
        std::printf(" %.2f |", static_cast<double>(total) / trials);
      }
      std::printf("\n");
    }
  }
  return 0;
}

/// Probability that one edge with both endpoints displaced uniformly in the ball of radius
/// `noise` passes the textural test (mean endpoint distance to the true face plane <= eps) and
/// the crease test (mean endpoint distance to the true edge line <= eps), eps 0.06.
int EdgeTests(int samples) {
  constexpr double kEps = 0.06;
  std::printf("| noise | P(textural test passes) | P(crease test passes) |\n|---|---|---|\n");
  for (const double noise : {0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35}) {
    Rng rng(MixSeed(1, RngStage::kSynth, static_cast<std::uint64_t>(noise * 100)));
    auto displacement = [&] {
      Vec3 v;
      do {
        v = Vec3(rng.Uniform(-noise, noise), rng.Uniform(-noise, noise), rng.Uniform(-noise, noise));
      } while (v.norm() > noise);
      return v;
    };
    int textural = 0;
    int crease = 0;
    for (int i = 0; i < samples; ++i) {  // edge along x; face plane z = 0; crease line = x axis
      const Vec3 a = displacement();
      const Vec3 b = displacement();
      textural += 0.5 * (std::abs(a.z()) + std::abs(b.z())) <= kEps ? 1 : 0;
      crease += 0.5 * (std::hypot(a.y(), a.z()) + std::hypot(b.y(), b.z())) <= kEps ? 1 : 0;
    }
    std::printf("| %.2f | %.3f | %.3f |\n", noise, static_cast<double>(textural) / samples,
                static_cast<double>(crease) / samples);
  }
  return 0;
}

/// Matching: plane q of `scene` (with its memberships) is matched by a detected plane p if their
/// normals are within 5 degrees and every inlier of q (mean endpoint distance) is within 3 eps
/// of p. Printed by the number of distinct lines (collinear parts merged) that support q, with
/// how many planes of `scene` pass the criterion against themselves (how strict it is).
void PrintMatching(const Scene& scene, const IdVector<PlaneId, Plane3>& detected, double epsilon,
                   const char* reference_name) {
  const double max_angle = 5.0 * std::numbers::pi / 180.0;
  const double tol = 3.0 * epsilon;
  const detect::CollinearGroups groups =
      detect::GroupCollinearSegments(scene.segments.raw(), 1e-3 * epsilon);
  std::vector<std::uint32_t> line_of(scene.segments.size());
  for (std::size_t g = 0; g < groups.members.NumRows(); ++g) {
    for (const SegmentId s : groups.members[SegmentId(g)]) line_of[s.index()] = g;
  }
  auto fraction_near = [&](const Plane3& p, const std::vector<SegmentId>& members) {
    std::size_t near = 0;
    for (const SegmentId s : members) {
      const double d =
          detect::SegmentPlaneDistance(scene.segments[s], p, SegmentDistance::kMeanEndpoint);
      near += d <= tol ? 1 : 0;
    }
    return members.empty() ? 0.0 : static_cast<double>(near) / members.size();
  };
  struct Bucket {
    const char* name;
    std::size_t planes = 0, matched = 0, matched_95 = 0, self = 0;
  };
  std::vector<Bucket> buckets = {{"<= 5"}, {"6-9"}, {">= 10"}, {"all"}};
  for (std::size_t q = 0; q < scene.planes.size(); ++q) {
    std::vector<SegmentId> members;
    std::vector<std::uint32_t> lines;
    for (std::size_t s = 0; s < scene.memberships.size(); ++s) {
      if (!scene.memberships[SegmentId(s)].Contains(PlaneId(q))) continue;
      members.emplace_back(s);
      lines.push_back(line_of[s]);
    }
    std::sort(lines.begin(), lines.end());
    const std::size_t num_lines =
        static_cast<std::size_t>(std::unique(lines.begin(), lines.end()) - lines.begin());
    const Plane3& ref = scene.planes[PlaneId(q)];
    double best_fraction = 0.0;  // of the reference inliers within 3 eps of one plane
    double best_angle_deg = 90.0;
    for (const Plane3& p : detected) {
      const double angle = std::acos(std::min(1.0, std::abs(p.normal.dot(ref.normal))));
      if (angle >= max_angle) continue;
      const double fraction = fraction_near(p, members);
      if (fraction > best_fraction) {
        best_fraction = fraction;
        best_angle_deg = angle * 180.0 / std::numbers::pi;
      }
    }
    const std::size_t own = num_lines >= 10 ? 2 : (num_lines >= 6 ? 1 : 0);
    for (const std::size_t b : {own, std::size_t{3}}) {
      ++buckets[b].planes;
      buckets[b].matched += best_fraction >= 1.0 ? 1 : 0;
      buckets[b].matched_95 += best_fraction >= 0.95 ? 1 : 0;
      buckets[b].self += fraction_near(ref, members) >= 1.0 ? 1 : 0;
    }
    if (best_fraction < 1.0 && std::getenv("LINESURF_STUDY_VERBOSE") != nullptr) {
      std::fprintf(stderr,
                   "unmatched reference plane %zu: %zu inliers on %zu lines, best %.3f within 3 eps "
                   "at %.2f deg\n",
                   q, members.size(), num_lines, best_fraction, best_angle_deg);
    }
  }
  std::printf("\n| %s planes by supporting lines | planes | matched | 95 %% of inliers "
              "within 3 eps | %s plane matches itself |\n|---|---|---|---|---|\n",
              reference_name, reference_name);
  for (const Bucket& b : buckets) {
    std::printf("| %s | %zu | %zu (%.1f %%) | %zu | %zu |\n", b.name, b.planes, b.matched,
                b.planes ? 100.0 * static_cast<double>(b.matched) / b.planes : 0.0, b.matched_95,
                b.self);
  }
}

int Andalusian(const char* path, int threads, int argc, char** argv) {
  Expected<Scene> read = io::ReadReferenceJson(path);
  if (!read) {
    std::fprintf(stderr, "%s\n", read.error().ToString().c_str());
    return 1;
  }
  Expected<pipeline::SanitizeResult> sane = pipeline::SanitizeScene(std::move(*read), {});
  if (!sane) {
    std::fprintf(stderr, "%s\n", sane.error().ToString().c_str());
    return 1;
  }
  const Scene& scene = sane->scene;
  PlaneDetectionOptions options;
  options.epsilon = 0.02;
  options.max_planes = 160;
  // Optional overrides for parameter studies: min_iterations confidence near_fraction max_planes
  // min_support max_failed_draws seed.
  if (argc > 4) options.min_iterations = std::atoll(argv[4]);
  if (argc > 5) options.confidence = std::atof(argv[5]);
  if (argc > 6) options.near_fraction = std::atof(argv[6]);
  if (argc > 7) options.max_planes = std::atoi(argv[7]);
  if (argc > 8) options.min_support = std::atoi(argv[8]);
  if (argc > 9) options.max_failed_draws = std::atoll(argv[9]);
  if (argc > 10) options.seed = std::strtoull(argv[10], nullptr, 10);
  RunContext ctx;
  ctx.num_threads = threads;
  Expected<PlaneDetectionResult> r = DetectPlanes(scene, options, ctx);
  if (!r) {
    std::fprintf(stderr, "%s\n", r.error().ToString().c_str());
    return 1;
  }
  const PlaneDetectionStats& st = r->stats;
  std::printf("| segments | %zu |\n|---|---|\n", scene.segments.size());
  std::printf("| planes before / after fusion | %d / %d (%d merges) |\n", st.planes_before_fusion,
              st.planes_after_fusion, st.merges);
  std::printf("| segments on 0 / 1 / 2 planes (L0/L1/L2) | %lld / %lld / %lld |\n",
              static_cast<long long>(st.num_l0), static_cast<long long>(st.num_l1),
              static_cast<long long>(st.num_l2));
  std::printf("| candidates evaluated / failed draws | %lld / %lld |\n",
              static_cast<long long>(st.candidates_evaluated),
              static_cast<long long>(st.failed_draws));
  std::printf("| runtime (s, %d threads) | %.2f (fusion %.3f) |\n", threads, st.seconds,
              st.seconds_fusion);
  std::printf("| distinct lines detected on | %lld |\n", static_cast<long long>(st.lines));
  if (std::getenv("LINESURF_STUDY_VERBOSE") != nullptr) {
    for (std::size_t p = 0; p < r->planes.size(); ++p) {
      const Plane3& pl = r->planes[PlaneId(p)];
      std::fprintf(stderr, "plane %zu: %u inliers, length %.1f, normal %.3f %.3f %.3f offset %.3f\n", p,
                   r->support[PlaneId(p)].inlier_count, r->support[PlaneId(p)].inlier_length,
                   pl.normal.x(), pl.normal.y(), pl.normal.z(), pl.Offset());
    }
  }
  PrintMatching(scene, r->planes, r->stats.epsilon, "reference");
  // Calibration: the same detector with the next seed, matched against this run's planes.
  PlaneDetectionOptions next = options;
  ++next.seed;
  Expected<PlaneDetectionResult> other = DetectPlanes(scene, next, ctx);
  if (!other) {
    std::fprintf(stderr, "%s\n", other.error().ToString().c_str());
    return 1;
  }
  Scene ours = scene;
  ours.planes = r->planes;
  ours.memberships = r->memberships;
  std::printf("\nThe same detector with seed %llu matched against this run (seed %llu):\n",
              static_cast<unsigned long long>(next.seed),
              static_cast<unsigned long long>(options.seed));
  PrintMatching(ours, other->planes, r->stats.epsilon, "our");
  return 0;
}

}  // namespace
}  // namespace linesurf

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "robustness") {
    const int exhaustive = argc > 2 ? std::atoi(argv[2]) : 64;
    const linesurf::synth::NoiseModel model =
        argc > 3 && std::string(argv[3]) == "gauss" ? linesurf::synth::NoiseModel::kGaussian
                                                    : linesurf::synth::NoiseModel::kUniformBall;
    const int trials = argc > 4 ? std::atoi(argv[4]) : 20;
    const bool near = argc > 5 && std::string(argv[5]) == "near";
    return linesurf::Robustness(exhaustive, model, trials, near);
  }
  if (mode == "edge-tests") return linesurf::EdgeTests(argc > 2 ? std::atoi(argv[2]) : 200000);
  if (mode == "andalusian" && argc > 2) {
    return linesurf::Andalusian(argv[2], argc > 3 ? std::atoi(argv[3]) : 0, argc, argv);
  }
  std::fprintf(stderr,
               "usage: %s robustness [exhaustive_max] [ball|gauss] [trials] [held|near] | "
               "edge-tests [samples] | "
               "andalusian PATH "
               "[threads [min_iterations [confidence [near_fraction [max_planes [min_support "
               "[max_failed_draws [seed]]]]]]]]\n",
               argv[0]);
  return 2;
}
