#include "engine/io/reference_system.h"

#include "linesurf/options.h"

#include "engine/core/exception.h"

#include <cctype>
#include <cmath>

namespace linesurf::io {
namespace {
constexpr const char* kReferenceSystemStage = "georeference";
}  // namespace

std::string EpsgCode(const std::string& crs) {
  const std::string prefix = "epsg:";
  bool valid = crs.size() > prefix.size();
  for (std::size_t i = 0; valid && i < crs.size(); ++i) {
    const auto c = static_cast<unsigned char>(crs[i]);
    valid = i < prefix.size() ? std::tolower(c) == prefix[i] : std::isdigit(c) != 0;
  }
  LINESURF_THROW_IF(!valid,
                    kInvalidOptions,
                    kReferenceSystemStage,
                    "crs: '" << crs << "' is not EPSG:CODE (e.g. EPSG:7415)");
  return crs.substr(prefix.size());
}

}  // namespace linesurf::io

namespace linesurf {

Status GeoreferenceOptions::Validate() const noexcept {
  return CatchAll("georeference", [&] {
    if (!crs.empty()) static_cast<void>(io::EpsgCode(crs));
    const double length = std::hypot(up[0], up[1], up[2]);
    LINESURF_THROW_IF(!std::isfinite(length) || length == 0.0,
                      kInvalidOptions,
                      "georeference",
                      "up = (" << up[0] << ", " << up[1] << ", " << up[2]
                               << ") is not a direction: it must be finite and not zero");
  });
}

}  // namespace linesurf
