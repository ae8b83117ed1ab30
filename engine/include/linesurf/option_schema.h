#pragma once
/// @file option_schema.h
/// @brief The one declaration of every option of ReconstructOptions and DetectOptions: its path,
/// command-line flag, group, help and range. The front ends visit it instead of listing options:
/// Validate checks the ranges, the CLI makes its flags and `--config` keys, the C API its names,
/// Python its fields, the report its `options` section and docs/user/cli_reference.md its table.
/// The default of an option is the initialiser of its field in options.h and exists nowhere else.

#include "linesurf/error.h"
#include "linesurf/options.h"

#include <cmath>
#include <cstdio>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace linesurf {
inline namespace v3 {

/// The values a numeric option accepts; a NaN or an infinity is refused whatever the range.
struct OptionRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< min itself is refused
  bool max_open = false;  ///< max itself is refused
};

/// One option as every front end names it.
struct OptionSpec {
  /// The C++ field path ("weights.visibility"): the C API's name, the Python attribute path, the
  /// `--config` key and the report's key.
  std::string_view path;
  /// The command-line flag without "--" ("w-visibility").
  std::string_view flag;
  /// The heading it is listed under in the docs and the help ("Detection", "Energy", ...).
  std::string_view group;
  std::string_view help;
  /// Numbers only; an optional number's range applies when it is set.
  OptionRange range;
};

namespace internal {

template <typename T, typename Plain>
concept OptionsOf = std::same_as<std::remove_const_t<T>, Plain>;

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr OptionRange kNonNegative{.min = 0.0};
inline constexpr OptionRange kPositive{.min = 0.0, .min_open = true};
inline constexpr OptionRange kWeight{.min = 0.0, .max = 1e6};
inline constexpr const char* kGroupDetection = "Detection";
inline constexpr const char* kGroupEnergy = "Energy";
inline constexpr const char* kGroupComplex = "Cell complex";
inline constexpr const char* kGroupSolver = "Solver";
inline constexpr const char* kGroupOutput = "Output";
inline constexpr const char* kGroupRun = "Run";

}  // namespace internal

/// Visits every option of `d` as visit(const OptionSpec&, field&), in the order the help lists
/// them. Paths start with "detection.", the field's name in ReconstructOptions and DetectOptions.
template <internal::OptionsOf<DetectionParameters> D, typename Visit>
void VisitOptions(D& d, Visit&& visit) {
  using internal::kGroupDetection;
  visit(OptionSpec{"detection.epsilon", "epsilon", kGroupDetection,
                   "Inlier tolerance eps, scene units (unset: estimated from the data)",
                   internal::kPositive},
        d.epsilon);
  visit(OptionSpec{"detection.epsilon_over_noise", "epsilon-over-noise", kGroupDetection,
                   "eps auto: eps = this x the robust noise scale of the plane residuals",
                   {.min = 0.0, .max = 20.0, .min_open = true}},
        d.epsilon_over_noise);
  visit(OptionSpec{"detection.relative_epsilon", "relative-epsilon", kGroupDetection,
                   "eps as a fraction of the scene diagonal (overrides epsilon)",
                   {.min = 0.0, .max = 0.5, .min_open = true, .max_open = true}},
        d.relative_epsilon);
  visit(OptionSpec{"detection.epsilon_fusion_factor", "epsilon-fusion-factor", kGroupDetection,
                   "Fusion thickness as a multiple of eps", {.min = 1.0}},
        d.epsilon_fusion_factor);
  visit(OptionSpec{"detection.theta_fusion_deg", "theta-fusion", kGroupDetection,
                   "Planes closer than this angle may merge, degrees",
                   {.min = 0.0, .max = 90.0, .min_open = true, .max_open = true}},
        d.theta_fusion_deg);
  visit(OptionSpec{"detection.p_fusion", "p-fusion", kGroupDetection,
                   "Minimum shared support of a merge, fraction of the smaller plane's inliers",
                   {.min = 0.0, .max = 1.0}},
        d.p_fusion);
  visit(OptionSpec{"detection.iterations", "iterations", kGroupDetection,
                   "Maximum candidate pairs per plane", {.min = 1.0}},
        d.iterations);
  visit(OptionSpec{"detection.max_planes", "max-planes", kGroupDetection,
                   "Maximum number of planes (per detection block)", {.min = 1.0}},
        d.max_planes);
  visit(OptionSpec{"detection.min_support", "min-support", kGroupDetection,
                   "Minimum inlier segments of a plane", {.min = 2.0}},
        d.min_support);
  visit(OptionSpec{"detection.support_gap", "support-gap", kGroupDetection,
                   "A plane whose support comes in pieces this many median line lengths apart "
                   "that disagree about it keeps its largest piece (0 = off)",
                   {.min = 0.0, .max = 1000.0}},
        d.support_gap);
  visit(OptionSpec{"detection.collinear_tolerance", "collinear-tolerance", kGroupDetection,
                   "Segments on one line within this x eps are detected as one (0 = off)",
                   {.min = 0.0, .max = 0.5}},
        d.collinear_tolerance);
  visit(OptionSpec{"detection.block_size", "detect-block-size", kGroupDetection,
                   "Per-block detection: cube side, scene units (0 = the whole scene at once; "
                   "reconstruct: automatic with the blocks engine)",
                   internal::kNonNegative},
        d.block_size);
  visit(OptionSpec{"detection.block_halo", "detect-block-halo", kGroupDetection,
                   "Halo of a detection block, fraction of its side",
                   {.min = 0.0, .max = 0.5, .max_open = true}},
        d.block_halo);
  visit(OptionSpec{"detection.block_max_segments", "detect-block-max-segments", kGroupDetection,
                   "Split a detection block with more lines than this into 8, recursively "
                   "(0 = never)",
                   internal::kNonNegative},
        d.block_max_segments);
}

/// Visits the weights; paths start with "weights.".
template <internal::OptionsOf<EnergyWeights> W, typename Visit>
void VisitOptions(W& w, Visit&& visit) {
  using internal::kGroupEnergy;
  using internal::kWeight;
  visit(OptionSpec{"weights.textural", "w-textural", kGroupEnergy, "Textural primitive weight",
                   kWeight},
        w.textural);
  visit(OptionSpec{"weights.structural", "w-structural", kGroupEnergy,
                   "Structural primitive weight", kWeight},
        w.structural);
  visit(OptionSpec{"weights.crease", "w-crease", kGroupEnergy,
                   "Crease weight of structural segments (unset: 0.2 in interior scenes, 0 in "
                   "exterior ones)",
                   kWeight},
        w.crease);
  visit(OptionSpec{"weights.visibility", "w-visibility", kGroupEnergy,
                   "Visibility weight lambda_vis", kWeight},
        w.visibility);
  visit(OptionSpec{"weights.edge", "w-edge", kGroupEnergy,
                   "Edge regularisation weight, per length / sigma", kWeight},
        w.edge);
  visit(OptionSpec{"weights.corner", "w-corner", kGroupEnergy,
                   "Corner regularisation weight, per corner", kWeight},
        w.corner);
  visit(OptionSpec{"weights.area", "w-area", kGroupEnergy,
                   "Surface area weight, per area / sigma^2", kWeight},
        w.area);
  visit(OptionSpec{"weights.viewpoint_prior", "w-prior", kGroupEnergy,
                   "Viewpoint prior weight, per observation of a full viewpoint cell", kWeight},
        w.viewpoint_prior);
  visit(OptionSpec{"weights.open_seam", "w-open-seam", kGroupEnergy,
                   "Blocks engine: weight of surface on block faces that carry no plane, per "
                   "area / sigma^2",
                   kWeight},
        w.open_seam);
}

/// Visits the solver's options; paths start with "solver.".
template <internal::OptionsOf<SolverOptions> S, typename Visit>
void VisitOptions(S& s, Visit&& visit) {
  using internal::kGroupSolver;
  visit(OptionSpec{"solver.backend", "solver", kGroupSolver,
                   "Labelling backend (auto: by model size; docs/design/solver.md)", {}},
        s.backend);
  visit(OptionSpec{"solver.time_limit_seconds", "time-limit", kGroupSolver,
                   "Solver wall-time limit, seconds (0 = none)", internal::kNonNegative},
        s.time_limit_seconds);
}

/// Visits the quality figures' options; paths start with "quality.".
template <internal::OptionsOf<QualityOptions> Q, typename Visit>
void VisitOptions(Q& q, Visit&& visit) {
  using internal::kGroupOutput;
  visit(OptionSpec{"quality.fit_factor", "fit-factor", kGroupOutput,
                   "Quality: a segment sample fits the surface within this x eps",
                   internal::kPositive},
        q.fit_factor);
  visit(OptionSpec{"quality.samples_per_segment", "quality-samples", kGroupOutput,
                   "Quality: samples per segment", {.min = 1.0, .max = 1024.0}},
        q.samples_per_segment);
  visit(OptionSpec{"quality.min_lines_per_component", "fragment-min-lines", kGroupOutput,
                   "A component holding fewer supported lines than this is a floating fragment",
                   internal::kNonNegative},
        q.min_lines_per_component);
}

/// Visits the thread count and seed of DetectOptions or ReconstructOptions (paths "num_threads",
/// "seed"). The CLI's flag of num_threads is its global -j/--threads.
template <typename O, typename Visit>
void VisitRunOptions(O& o, Visit&& visit) {
  using internal::kGroupRun;
  visit(OptionSpec{"num_threads", "threads", kGroupRun,
                   "Worker threads (0 = automatic); results do not depend on it",
                   {.min = 0.0, .max = static_cast<double>(kMaxThreads)}},
        o.num_threads);
  visit(OptionSpec{"seed", "seed", kGroupRun,
                   "Seed of every random stream: same input + options + seed, same result", {}},
        o.seed);
}

/// Every option of DetectOptions.
template <internal::OptionsOf<DetectOptions> O, typename Visit>
void VisitOptions(O& o, Visit&& visit) {
  VisitOptions(o.detection, visit);
  VisitRunOptions(o, visit);
}

/// Every option of ReconstructOptions.
template <internal::OptionsOf<ReconstructOptions> O, typename Visit>
void VisitOptions(O& o, Visit&& visit) {
  using internal::kGroupComplex;
  using internal::kGroupEnergy;
  using internal::kGroupOutput;
  visit(OptionSpec{"plane_source", "planes", internal::kGroupDetection,
                   "Planes: detect them, or use the input's", {}},
        o.plane_source);
  VisitOptions(o.detection, visit);
  visit(OptionSpec{"scene_mode", "scene", kGroupEnergy,
                   "Boundary: box cells empty (exterior), full (interior), or decided from the "
                   "viewpoints and planes", {}},
        o.scene_mode);
  VisitOptions(o.weights, visit);
  visit(OptionSpec{"sigma", "sigma", kGroupEnergy,
                   "Scale sigma of the evidence, scene units (unset: the median segment length)",
                   internal::kPositive},
        o.sigma);
  visit(OptionSpec{"samples_per_sigma", "samples-per-sigma", kGroupEnergy,
                   "Evidence samples per sigma of segment length",
                   {.min = 0.0, .max = 1000.0, .min_open = true}},
        o.samples_per_sigma);
  visit(OptionSpec{"structural_as_textural", "structural-as-textural", kGroupEnergy,
                   "Ablation: structural segments count as two textural ones", {}},
        o.structural_as_textural);
  VisitOptions(o.solver, visit);
  visit(OptionSpec{"engine", "engine", kGroupComplex,
                   "Cell complex: the scene box as one block (one arrangement), or blocks", {}},
        o.engine);
  visit(OptionSpec{"block_size", "block-size", kGroupComplex,
                   "Blocks engine: side of the base blocks, scene units (0 = automatic)",
                   internal::kNonNegative},
        o.block_size);
  visit(OptionSpec{"block_margin", "block-margin", kGroupComplex,
                   "Blocks engine: blocks a plane's support region is dilated by, fractions "
                   "allowed",
                   {.min = 0.0, .max = 64.0}},
        o.block_margin);
  visit(OptionSpec{"box_margin", "box-margin", kGroupComplex,
                   "The scene box grows by this fraction of its extent on each side",
                   {.min = 0.0, .max = 10.0, .min_open = true}},
        o.box_margin);
  visit(OptionSpec{"measure_quality", "quality", kGroupOutput,
                   "Figures without ground truth in the report (data fit, visibility, "
                   "components)", {}},
        o.measure_quality);
  VisitOptions(o.quality, visit);
  visit(OptionSpec{"remove_floating_fragments", "remove-fragments", kGroupOutput,
                   "Drop floating fragments when another component holds more supported lines", {}},
        o.remove_floating_fragments);
  visit(OptionSpec{"repair_pinches", "repair-pinches", kGroupOutput,
                   "Relabel the cheapest cell where parts meet only along an edge or at a point "
                   "(one valid solid, no split vertices)", {}},
        o.repair_pinches);
  visit(OptionSpec{"triangulate", "triangulate", kGroupOutput,
                   "Triangles instead of convex polygons", {}},
        o.triangulate);
  visit(OptionSpec{"merge_coplanar", "merge-coplanar", kGroupOutput,
                   "Neighbouring faces of one plane with one outward side become one polygon "
                   "(may be non-convex; not with triangulate)", {}},
        o.merge_coplanar);
  VisitRunOptions(o, visit);
}

/// The range as the docs and messages write it: "> 0", ">= 1", "[0, 1000]", "(0, 20]"; empty when
/// every finite number is accepted.
[[nodiscard]] inline std::string OptionRangeText(const OptionRange& r) {
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return std::string(text);
  };
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of string operator+.
  std::string text;
  if (std::isinf(r.min) && std::isinf(r.max)) return text;
  if (std::isinf(r.max)) {
    text = r.min_open ? "> " : ">= ";
    text += number(r.min);
    return text;
  }
  text = r.min_open ? "(" : "[";
  text += number(r.min);
  text += ", ";
  text += number(r.max);
  text += r.max_open ? ")" : "]";
  return text;
}

/// Why `value` is outside spec.range ("must be in (0, 20]"), or an empty string when it is in.
[[nodiscard]] inline std::string OptionRangeViolation(const OptionSpec& spec, double value) {
  const OptionRange& r = spec.range;
  const bool below = r.min_open ? !(value > r.min) : !(value >= r.min);
  const bool above = r.max_open ? !(value < r.max) : !(value <= r.max);
  if (std::isfinite(value) && !below && !above) return {};
  const std::string range = OptionRangeText(r);
  if (range.empty()) return "must be finite";
  std::string why = range[0] == '[' || range[0] == '(' ? "must be in " : "must be ";
  why += range;
  return why;
}

namespace internal {

template <typename T>
inline constexpr bool kIsOptional = false;
template <typename T>
inline constexpr bool kIsOptional<std::optional<T>> = true;

}  // namespace internal

/// Why `field` is not a value its spec accepts, or an empty string: a number out of its range,
/// an enumerator outside its enum. Booleans and strings accept every value.
template <typename T>
[[nodiscard]] std::string OptionValueViolation(const OptionSpec& spec, const T& field) {
  if constexpr (std::is_enum_v<T>) {
    return OptionEnum<T>::Name(field)[0] ? std::string() : std::string("is not a valid value");
  } else if constexpr (internal::kIsOptional<T>) {
    return field ? OptionRangeViolation(spec, static_cast<double>(*field)) : std::string();
  } else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    return OptionRangeViolation(spec, static_cast<double>(field));
  } else {
    return {};
  }
}

/// kInvalidOptions naming the first option of `options` (in VisitOptions order) whose value its
/// spec refuses: "detection.support_gap must be in [0, 1000]". The rules that tie options
/// together are the Validate() of the options struct.
template <typename Options>
[[nodiscard]] Status ValidateOptionValues(const Options& options) {
  Status first;
  VisitOptions(options, [&first](const OptionSpec& spec, const auto& field) {
    if (!first) return;
    if (std::string why = OptionValueViolation(spec, field); !why.empty()) {
      std::string message(spec.path);
      message += ' ';
      message += why;
      first = Error{ErrorCode::kInvalidOptions, "options", std::move(message)};
    }
  });
  return first;
}

}  // namespace v3
}  // namespace linesurf
