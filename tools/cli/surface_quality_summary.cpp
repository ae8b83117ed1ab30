#include "tools/cli/surface_quality_summary.h"

#include <cstdio>

namespace linesurf::cli {

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
