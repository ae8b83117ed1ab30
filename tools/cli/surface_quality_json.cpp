#include "tools/cli/surface_quality_json.h"

#include <cstdio>

namespace linesurf::cli {

nlohmann::json SurfaceQualityJson(const SurfaceQuality& q) {
  nlohmann::json components = nlohmann::json::array();
  for (std::size_t i = 0; i < q.components.size() && i < kMaxListedComponents; ++i) {
    const ComponentQuality& c = q.components[i];
    components.push_back({{"faces", c.faces},
                          {"volume", c.volume},
                          {"supported_length", c.supported_length},
                          {"supported_segments", c.supported_segments},
                          {"supported_lines", c.supported_lines},
                          {"floating", c.floating}});
  }
  nlohmann::json off = q.planes_off_surface;
  return {{"epsilon", q.epsilon},
          {"fit_distance", q.fit_distance},
          {"supported_segments", q.supported_segments},
          {"supported_length", q.supported_length},
          {"data_fit", q.data_fit},
          {"visibility_consistency", q.visibility_consistency},
          {"visibility_consistency_all_segments", q.visibility_consistency_all},
          {"num_components", q.components.size()},
          {"enclosed_volume", q.enclosed_volume},
          {"largest_component_share", q.largest_component_share},
          {"floating_fragments", q.floating_fragments},
          {"components", std::move(components)},
          {"planes_off_surface", std::move(off)}};
}

std::string SurfaceQualitySummary(const SurfaceQuality& q, const std::string& prefix) {
  char buf[512];
  std::snprintf(buf,
                sizeof buf,
                "%sdata fit %.1f %% (supported length within %.4g), visibility consistency "
                "%.1f %% (supported segments; %.1f %% all)\n%s%zu components, largest %.1f %% of "
                "the enclosed volume %.6g, %zu floating fragments; %zu planes on no face\n",
                prefix.c_str(),
                100.0 * q.data_fit,
                q.fit_distance,
                100.0 * q.visibility_consistency,
                100.0 * q.visibility_consistency_all,
                prefix.c_str(),
                q.components.size(),
                100.0 * q.largest_component_share,
                q.enclosed_volume,
                q.floating_fragments,
                q.planes_off_surface.size());
  return buf;
}

}  // namespace linesurf::cli
