#include "tools/gen/synthetic_meta.h"

#include <array>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/core/exception.h"

namespace linesurf::synth {
namespace {

const char* const kSyntheticMetaStage = "write_synthetic_meta";

nlohmann::json ToJson(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

const char* NoiseModelName(NoiseModel m) {
  return m == NoiseModel::kGaussian ? "gaussian" : m == NoiseModel::kDepth ? "depth" : "uniform_ball";
}

}  // namespace

std::string SyntheticMetaJson(const SyntheticScene& s) {
  nlohmann::ordered_json j;
  j["format"] = "linesurf-synthetic-meta";
  j["version"] = 1;
  const SynthSpec& spec = s.spec;
  nlohmann::ordered_json js;
  js["family"] = spec.family;
  js["seed"] = spec.seed;
  js["size"] = spec.size;
  js["noise_sigma"] = spec.noise_sigma;
  js["noise_model"] = NoiseModelName(spec.noise_model);
  js["outlier_model"] = spec.outlier_model == OutlierModel::kNear ? "near" : "uniform";
  js["outlier_fraction"] = spec.outlier_fraction;
  js["outlier_count"] = spec.outlier_count ? nlohmann::ordered_json(*spec.outlier_count) : nullptr;
  js["max_pieces"] = spec.max_pieces ? nlohmann::ordered_json(*spec.max_pieces) : nullptr;
  js["max_trim"] = spec.max_trim ? nlohmann::ordered_json(*spec.max_trim) : nullptr;
  js["max_views"] = spec.max_views;
  js["residual_split"] = spec.residual_split;
  js["max_view_trim"] = spec.max_view_trim;
  js["scale"] = spec.scale;
  js["rotation_axis"] = spec.rotation_axis;
  js["rotation_degrees"] = spec.rotation_degrees;
  js["offset"] = spec.offset;
  j["spec"] = js;
  j["up"] = UpDirection(spec);
  j["interior"] = s.interior;
  nlohmann::ordered_json gt;
  gt["volume"] = s.ground_truth_volume;
  gt["vertices"] = s.ground_truth.vertices.size();
  gt["faces"] = s.ground_truth.NumFaces();
  j["ground_truth"] = gt;
  const std::array<std::size_t, 3> counts = CountKinds(s.kinds);
  nlohmann::ordered_json jc;
  jc["segments"] = s.kinds.size();
  jc["structural"] = counts[0];
  jc["textural"] = counts[1];
  jc["outlier"] = counts[2];
  jc["viewpoints"] = s.scene.viewpoints.size();
  jc["observations"] = s.scene.observations.NumItems();
  jc["hidden_pieces_dropped"] = s.num_hidden_dropped;
  j["counts"] = jc;
  nlohmann::ordered_json planes = nlohmann::ordered_json::array();
  for (const Plane3& p : s.true_planes) {
    nlohmann::ordered_json jp;
    jp["point"] = ToJson(p.point);
    jp["normal"] = ToJson(p.normal);
    planes.push_back(jp);
  }
  j["planes"] = planes;
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < s.kinds.size(); ++i) {
    nlohmann::ordered_json js_seg;
    js_seg["kind"] = SegmentKindName(s.kinds[i]);
    nlohmann::ordered_json planes_of = nlohmann::ordered_json::array();
    const PlaneMembership& m = s.scene.memberships[SegmentId(i)];
    for (std::uint8_t k = 0; k < m.count; ++k) planes_of.push_back(m.planes[k].value());
    js_seg["planes"] = planes_of;
    segments.push_back(js_seg);
  }
  j["segments"] = segments;
  return j.dump(1) + "\n";
}

Status WriteSyntheticMeta(const SyntheticScene& scene, const std::filesystem::path& path) noexcept {
  return CatchAll(kSyntheticMetaStage, [&] {
    const std::string text = SyntheticMetaJson(scene);
    std::ofstream out(path, std::ios::binary);
    LINESURF_THROW_IF(
        !out, kInvalidInput, kSyntheticMetaStage, path.string() << ": cannot open for writing");
    out << text;
    out.close();
    LINESURF_THROW_IF(!out, kInvalidInput, kSyntheticMetaStage, path.string() << ": write failed");
  });
}

}  // namespace linesurf::synth
