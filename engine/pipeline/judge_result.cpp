#include "engine/pipeline/judge_result.h"

#include <sstream>

namespace linesurf::pipeline {
namespace {

constexpr const char* kJudgeResultStage = "reconstruct";
/// A closed surface needs at least this many planes (a tetrahedron).
constexpr std::size_t kMinPlanesForSolid = 4;
/// Beyond this multiple of the scene diagonal, sigma makes every data term negligible next to
/// the regularisation (costs are length / sigma).
constexpr double kNegligibleSigmaFactor = 1e3;
/// Beyond this fraction of the scene diagonal, the detection tolerance eps swallows the scene.
constexpr double kHugeEpsilonFraction = 0.1;
/// Above this share of its area on seams without a plane, a block-engine surface is mostly the
/// partition's block faces, not detected planes (a box of blocks instead of the scene).
constexpr double kOpenSeamShare = 0.05;

std::string ModeName(bool interior) { return interior ? "interior" : "exterior"; }

double Share(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

/// "E of N observing viewpoints", or "E of N viewpoints (an even sample of M observing)".
std::string EnclosedCount(const SceneModeDecision& d) {
  std::ostringstream os;
  os << d.enclosed_viewpoints << " of " << d.observing_viewpoints;
  if (d.sampled_from > d.observing_viewpoints) {
    os << " viewpoints (an even sample of " << d.sampled_from << " observing)";
  } else {
    os << " observing viewpoints";
  }
  return os.str();
}

void WarnSceneMode(const ResultFacts& f,
                   const SceneModeOptions& mode_options,
                   std::vector<std::string>& warnings) {
  const SceneModeDecision& d = f.decision;
  if (d.observing_viewpoints == 0) return;
  const double share = Share(d.enclosed_viewpoints, d.observing_viewpoints);
  std::ostringstream os;
  if (f.auto_mode && d.weak) {
    os << "scene mode auto chose " << ModeName(f.interior)
       << " on weak evidence: " << EnclosedCount(d)
       << " are enclosed by planes; choose the scene mode (exterior or interior) explicitly";
  } else if (!f.auto_mode && f.interior && share < mode_options.weak_low) {
    os << "scene mode interior was requested, but only " << EnclosedCount(d)
       << " are enclosed by planes (the scene looks like an exterior)";
  } else if (!f.auto_mode && !f.interior && share > mode_options.weak_high) {
    os << "scene mode exterior was requested, but " << EnclosedCount(d)
       << " are enclosed by planes (the scene looks like an interior)";
  }
  if (!os.str().empty()) warnings.push_back(os.str());
}

/// Why the surface came out empty, most specific causes first.
std::string EmptySurfaceCauses(const ResultFacts& f) {
  std::vector<std::string> causes;
  std::ostringstream os;
  if (f.observing_viewpoints == 0) {
    os << "no viewpoint observes a segment, so no sight ray carries evidence";
    if (f.viewpoints_dropped > 0) {
      os << " (" << f.viewpoints_dropped
         << " viewpoints dropped by sanitation: non-finite coordinate or beyond the bound)";
    }
    causes.push_back(os.str());
    os.str("");
  }
  if (f.planes_in_complex < kMinPlanesForSolid) {
    os << "only " << f.planes_in_complex << " plane(s) split the box (" << f.planes
       << " found), a closed surface needs at least " << kMinPlanesForSolid;
    causes.push_back(os.str());
    os.str("");
  }
  if (!f.has_data_weight) {
    causes.emplace_back(
        "every data weight (textural, structural, visibility, viewpoint prior) is 0");
  }
  if (f.sigma > kNegligibleSigmaFactor * f.scene_diagonal) {
    os << "sigma " << f.sigma << " is more than " << kNegligibleSigmaFactor
       << " times the scene diagonal " << f.scene_diagonal
       << ", which makes every data term negligible";
    causes.push_back(os.str());
    os.str("");
  }
  if (f.samples > 0 && 2 * f.grazing_samples > f.samples) {
    os << f.grazing_samples << " of " << f.samples
       << " segment samples carry no evidence because their viewpoint lies in the segment's "
          "plane (are the viewpoints on the segments?)";
    causes.push_back(os.str());
    os.str("");
  }
  if (f.interior && 2 * f.viewpoints_in_full_cells > f.observing_viewpoints) {
    os << f.viewpoints_in_full_cells << " of " << f.observing_viewpoints
       << " observing viewpoints lie in cells fixed or labelled full (is it an exterior "
          "scene?)";
    causes.push_back(os.str());
    os.str("");
  }
  if (causes.empty()) causes.emplace_back("the evidence does not separate full from empty space");
  std::string joined;
  for (const std::string& c : causes) joined += (joined.empty() ? "" : "; ") + c;
  return joined;
}

}  // namespace

ResultJudgement JudgeResult(const ResultFacts& f) {
  ResultJudgement j;
  WarnSceneMode(f, SceneModeOptions{}, j.warnings);
  if (!f.plane_cap_warning.empty()) j.warnings.push_back(f.plane_cap_warning);
  if (f.detection_epsilon > kHugeEpsilonFraction * f.scene_diagonal) {
    std::ostringstream os;
    os << "plane detection tolerance eps " << f.detection_epsilon << " exceeds "
       << kHugeEpsilonFraction << " of the scene diagonal " << f.scene_diagonal
       << ": is the scene in other units? (use a relative epsilon)";
    j.warnings.push_back(os.str());
  }
  if (f.viewpoints_in_full_cells > 0) {
    std::ostringstream os;
    os << f.viewpoints_in_full_cells << " of " << f.observing_viewpoints
       << " observing viewpoints lie inside the solid (their cell is full)";
    j.warnings.push_back(os.str());
  }
  if (f.mesh_area > 0.0 && f.open_seam_area > kOpenSeamShare * f.mesh_area) {
    std::ostringstream os;
    os.precision(3);
    os << 100.0 * f.open_seam_area / f.mesh_area << " % of the surface area (" << f.open_seam_faces
       << " faces) lies on block faces that carry no detected plane: the solid is closed by the "
          "block partition, not by the data (planes missing, or --block-size too small for the "
          "scene; try the automatic block size or a larger --block-margin)";
    j.warnings.push_back(os.str());
  }
  std::ostringstream os;
  if (f.mesh_faces == 0) {
    os << "the surface is empty: all " << f.cells << " cells are "
       << (f.interior ? "full" : "empty") << " (" << ModeName(f.interior)
       << " scene): " << EmptySurfaceCauses(f);
    for (const std::string& w : j.warnings) os << "; " << w;
    j.error = Error{ErrorCode::kDegenerate, kJudgeResultStage, os.str()};
    return j;
  }
  if (!f.topology.IsManifold()) {
    // Fans are named on a closed surface only: an open one reports its edges.
    const bool closed = f.topology.paired;
    os << "the surface is not " << (closed ? "2-manifold" : "closed") << " ("
       << f.topology.num_unpaired_half_edges << " boundary or repeated edges, "
       << (closed ? f.topology.num_non_manifold_vertices : 0) << " non-manifold vertices)";
    j.warnings.push_back(os.str());
    return j;
  }
  const double volume = f.topology.signed_volume;
  if (f.interior ? !(volume < 0.0) : !(volume > 0.0)) {
    os << "the surface is inverted: signed volume " << volume << " for an " << ModeName(f.interior)
       << " scene (expected " << (f.interior ? "< 0" : "> 0") << ")";
    j.error = Error{ErrorCode::kDegenerate, kJudgeResultStage, os.str()};
  }
  return j;
}

}  // namespace linesurf::pipeline
