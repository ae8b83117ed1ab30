#include "engine/pipeline/evidence.h"

#include "linesurf/option_schema.h"

#include "engine/core/median_segment_length.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/core/exception.h"
#include "engine/pipeline/segment_evidence.h"

namespace linesurf::pipeline {
namespace {

/// Largest fixed-point total: every accumulated cost must stay below it, or the sums wrap.
constexpr double kFixedPointLimit = 9.2233720368547758e18 / kEvidenceFixedPointScale;  // 2^63 / scale
/// Smallest sigma, as a fraction of the box diagonal: finer scales resolve nothing and make the
/// per-length costs (edge weight * length / sigma) overflow.
constexpr double kMinSigmaRelative = 1e-9;

}  // namespace

double CreaseWeight(const EnergyOptions& options, BoundaryMode boundary) {
  if (options.weights.crease) return *options.weights.crease;
  return boundary == BoundaryMode::kInterior ? kInteriorCreaseWeight : 0.0;
}

Status EnergyOptions::Validate() const {
  const auto bad = [](const char* field, const std::string& why) -> Status {
    return Error{ErrorCode::kInvalidOptions, "energy_options", std::string(field) + " " + why};
  };
  if (Status s = ValidateOptionValues(weights); !s) return s;
  if (sigma && !(std::isfinite(*sigma) && *sigma > 0.0)) return bad("sigma", "must be > 0");
  if (!(samples_per_sigma > 0.0 && samples_per_sigma <= 1000.0)) {
    return bad("samples_per_sigma", "must be in (0, 1000]");
  }
  if (max_samples_per_segment < 1 || max_samples_per_segment > 100000) {
    return bad("max_samples_per_segment", "must be in [1, 100000]");
  }
  if (!(min_crease_angle_deg >= 0.0 && min_crease_angle_deg <= 45.0)) {
    return bad("min_crease_angle_deg", "must be in [0, 45]");
  }
  return {};
}

double DefaultSigma(const Scene& scene) {
  const double median = MedianSegmentLength(scene);
  return median > 0.0 ? median : 1.0;
}

Status CheckEnergyScale(const Scene& scene, const Box3& box, const EnergyOptions& options) {
  const double sigma = options.sigma ? *options.sigma : DefaultSigma(scene);
  const double diagonal = box.Extent().norm();
  std::ostringstream why;
  if (!(sigma >= kMinSigmaRelative * diagonal)) {
    why << "sigma " << sigma << " is below " << kMinSigmaRelative << " of the scene box diagonal ("
        << diagonal << "): give a sigma near the typical segment length";
    return Error{ErrorCode::kInvalidOptions, "energy_options", why.str()};
  }
  double length_views = 0.0;
  for (std::size_t s = 0; s < scene.NumSegments(); ++s) {
    const double length = scene.segments[SegmentId(s)].Length();
    length_views += length * static_cast<double>(scene.observations[SegmentId(s)].size());
  }
  const double weight =
      std::max({options.weights.textural, options.weights.structural, options.weights.visibility});
  // A structural segment feeds its group and the visibility of its rays: at most 2 terms.
  const double total =
      2.0 * weight * length_views / sigma +
      options.weights.viewpoint_prior * static_cast<double>(scene.observations.NumItems());
  if (!(total < kFixedPointLimit)) {
    why << "sigma " << sigma << " with weights up to " << weight << " gives evidence totals of "
        << total << ", beyond the " << kFixedPointLimit
        << " the accumulators hold: raise sigma or lower the weights";
    return Error{ErrorCode::kInvalidOptions, "energy_options", why.str()};
  }
  return {};
}

}  // namespace linesurf::pipeline
