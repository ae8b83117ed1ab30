// `linesurf info INPUT`: what a scene file holds (counts, extent, histograms, warnings).

#include "linesurf/linesurf.h"

#include "tools/cli/commands.h"
#include "tools/cli/number_text.h"
#include "tools/cli/output_files.h"
#include "tools/cli/scene_input.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

namespace linesurf::cli {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Upper bounds (inclusive) of the views-per-segment bins; the last bin is open.
constexpr std::size_t kViewBinUpper[] = {0, 1, 2, 5, 10, 20, 50, 100};

struct InfoArgs {
  SceneInputArgs scene;
  bool json = false;
};

std::string VecText(const Vector3& v) {
  return "[" + ShortNumber(v[0]) + ", " + ShortNumber(v[1]) + ", " + ShortNumber(v[2]) + "]";
}

nlohmann::json VecJson(const Vector3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

bool AllFinite(const Vector3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

double Norm(const Vector3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// An axis-aligned box of finite points (empty until the first Extend).
struct Bounds {
  Vector3 min{kInf, kInf, kInf};
  Vector3 max{-kInf, -kInf, -kInf};

  void Extend(const Vector3& p) {
    for (int k = 0; k < 3; ++k) {
      min[k] = std::min(min[k], p[k]);
      max[k] = std::max(max[k], p[k]);
    }
  }
  [[nodiscard]] bool IsEmpty() const { return !(min[0] <= max[0]); }
  [[nodiscard]] Vector3 Extent() const {
    return {max[0] - min[0], max[1] - min[1], max[2] - min[2]};
  }
};

nlohmann::json BoxJson(const Bounds& box) {
  if (box.IsEmpty()) return nullptr;
  return {{"min", VecJson(box.min)},
          {"max", VecJson(box.max)},
          {"extent", VecJson(box.Extent())},
          {"diagonal", Norm(box.Extent())}};
}

/// Everything `info` reports, as JSON (the text output is rendered from it).
nlohmann::json Describe(const SceneData& scene) {
  nlohmann::json info;
  info["segments"] = scene.segments.size();
  info["viewpoints"] = scene.viewpoints.size();
  info["observations"] = scene.observations.size();
  info["residuals"] = scene.residuals.size();
  info["planes"] = scene.planes.size();
  if (!scene.planes.empty() || !scene.memberships.empty()) {
    std::vector<int> planes_of(scene.segments.size(), 0);
    for (const Membership& m : scene.memberships) ++planes_of[m.segment];
    std::size_t counts[3] = {0, 0, 0};
    for (const int n : planes_of) ++counts[std::min(n, 2)];
    info["segments_by_plane_count"] = {counts[0], counts[1], counts[2]};
  }
  Bounds segments_box, all_box;
  std::vector<double> lengths;
  lengths.reserve(scene.segments.size());
  for (const Segment& s : scene.segments) {
    if (AllFinite(s.p1) && AllFinite(s.p2)) {
      segments_box.Extend(s.p1);
      segments_box.Extend(s.p2);
      const double length = Norm({s.p2[0] - s.p1[0], s.p2[1] - s.p1[1], s.p2[2] - s.p1[2]});
      if (std::isfinite(length)) lengths.push_back(length);  // overflow (|x| ~ 1e300): not binned
    }
  }
  all_box = segments_box;
  for (const Vector3& v : scene.viewpoints) {
    if (AllFinite(v)) all_box.Extend(v);
  }
  info["bounding_box"] = BoxJson(segments_box);
  info["bounding_box_with_viewpoints"] = BoxJson(all_box);

  std::vector<std::size_t> views_of(scene.segments.size(), 0);
  for (const Observation& o : scene.observations) ++views_of[o.segment];
  nlohmann::json views = nlohmann::json::array();
  std::vector<std::size_t> view_bins(std::size(kViewBinUpper) + 1, 0);
  for (const std::size_t n : views_of) {
    const auto* bin = std::lower_bound(std::begin(kViewBinUpper), std::end(kViewBinUpper), n);
    ++view_bins[static_cast<std::size_t>(bin - std::begin(kViewBinUpper))];
  }
  std::size_t lower = 0;
  for (std::size_t b = 0; b < view_bins.size(); ++b) {
    const bool open = b == std::size(kViewBinUpper);
    const std::string label = open ? std::to_string(lower) + "+"
                              : lower == kViewBinUpper[b]
                                  ? std::to_string(lower)
                                  : std::to_string(lower) + "-" + std::to_string(kViewBinUpper[b]);
    views.push_back({{"views", label}, {"segments", view_bins[b]}});
    if (!open) lower = kViewBinUpper[b] + 1;
  }
  info["views_per_segment"] = views;

  if (!lengths.empty()) {
    std::sort(lengths.begin(), lengths.end());
    auto quantile = [&](double q) {
      return lengths[static_cast<std::size_t>(q * static_cast<double>(lengths.size() - 1) + 0.5)];
    };
    info["segment_length"] = {{"min", lengths.front()}, {"p05", quantile(0.05)},
                              {"p25", quantile(0.25)},  {"median", quantile(0.5)},
                              {"p75", quantile(0.75)},  {"p95", quantile(0.95)},
                              {"max", lengths.back()}};
    // Histogram over octaves [2^k, 2^(k+1)); zero lengths get their own bin.
    nlohmann::json bins = nlohmann::json::array();
    std::size_t zero = 0, i = 0;
    while (i < lengths.size() && !(lengths[i] > 0.0)) ++zero, ++i;
    if (zero > 0) bins.push_back({{"from", 0.0}, {"to", 0.0}, {"segments", zero}});
    while (i < lengths.size()) {
      const double from = std::exp2(std::floor(std::log2(lengths[i])));
      const double to = 2.0 * from;
      std::size_t count = 0;
      while (i < lengths.size() && lengths[i] < to) ++count, ++i;
      bins.push_back({{"from", from}, {"to", to}, {"segments", count}});
    }
    info["segment_length_histogram"] = bins;
  }
  return info;
}

void PrintText(const nlohmann::json& info, const std::string& input) {
  std::cout << "input: " << input << "\n";
  for (const char* key : {"segments", "viewpoints", "observations", "residuals", "planes"}) {
    std::cout << key << ": " << info[key].get<std::size_t>() << "\n";
  }
  if (info.contains("segments_by_plane_count")) {
    const auto& c = info["segments_by_plane_count"];
    std::cout << "segments with 0 / 1 / 2 planes: " << c[0].get<std::size_t>() << " / "
              << c[1].get<std::size_t>() << " / " << c[2].get<std::size_t>() << "\n";
  } else {
    std::cout << "segments with 0 / 1 / 2 planes: (no plane memberships in the input)\n";
  }
  for (const char* key : {"bounding_box", "bounding_box_with_viewpoints"}) {
    const auto& b = info[key];
    std::cout << (std::string(key) == "bounding_box" ? "bounding box (segments): "
                                                     : "bounding box (with viewpoints): ");
    if (b.is_null()) {
      std::cout << "(empty)\n";
      continue;
    }
    const auto vec = [](const nlohmann::json& a) {
      return Vector3{a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
    };
    const Vector3 e = vec(b["extent"]);
    std::cout << VecText(vec(b["min"])) << " .. " << VecText(vec(b["max"])) << ", extent "
              << ShortNumber(e[0]) << " x " << ShortNumber(e[1]) << " x " << ShortNumber(e[2]) << ", diagonal "
              << ShortNumber(b["diagonal"].get<double>()) << "\n";
  }
  std::cout << "views per segment:";
  for (const auto& bin : info["views_per_segment"]) {
    std::cout << "  " << bin["views"].get<std::string>() << ": " << bin["segments"].get<std::size_t>();
  }
  std::cout << "\n";
  if (info.contains("segment_length")) {
    const auto& l = info["segment_length"];
    std::cout << "segment length: min " << ShortNumber(l["min"].get<double>()) << ", p05 "
              << ShortNumber(l["p05"].get<double>()) << ", p25 " << ShortNumber(l["p25"].get<double>())
              << ", median " << ShortNumber(l["median"].get<double>()) << ", p75 "
              << ShortNumber(l["p75"].get<double>()) << ", p95 " << ShortNumber(l["p95"].get<double>())
              << ", max " << ShortNumber(l["max"].get<double>()) << "\n";
    std::cout << "segment length histogram:\n";
    for (const auto& bin : info["segment_length_histogram"]) {
      std::cout << "  [" << ShortNumber(bin["from"].get<double>()) << ", " << ShortNumber(bin["to"].get<double>())
                << "): " << bin["segments"].get<std::size_t>() << "\n";
    }
  }
  const auto& warnings = info["warnings"];
  std::cout << "warnings: " << warnings.size() << "\n";
  for (const auto& w : warnings) std::cout << "  - " << w.get<std::string>() << "\n";
}

}  // namespace

Command AddInfoCommand(CLI::App& app, CommonOptions& /*common*/) {
  auto args = std::make_shared<InfoArgs>();
  Command cmd;
  cmd.app = app.add_subcommand(
      "info", "Describe a scene file: counts, bounding box, histograms, sanitation warnings");
  AddSceneInputOptions(*cmd.app, args->scene);
  cmd.app->add_flag("--json", args->json, "Print the description as JSON on stdout");
  cmd.run = [args]() -> int {
    OutputFiles files("info");
    args->scene.AddInputsTo(files);
    if (Status s = files.Prepare(); !s) return ReportError(s.error());
    Expected<ReadSceneResult> read = ReadScene(args->scene.input, args->scene.Options());
    if (!read) return ReportError(read.error());
    nlohmann::json info = Describe(read->scene);
    nlohmann::json warnings = read->warnings;
    // What sanitation would fix or drop before a reconstruction.
    Expected<SanitizedScene> sanitized = SanitizeScene(read->scene);
    if (sanitized) {
      for (const std::string& w : sanitized->warnings) warnings.push_back("sanitation: " + w);
    }
    info["warnings"] = warnings;
    if (args->json) {
      info["input"] = args->scene.input;
      std::cout << info.dump(2) << "\n";
    } else {
      PrintText(info, args->scene.input);
    }
    return sanitized ? kExitOk : ReportError(sanitized.error(), args->scene.input);
  };
  return cmd;
}

}  // namespace linesurf::cli
