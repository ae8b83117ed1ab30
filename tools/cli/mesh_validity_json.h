#pragma once
// The validity classes of a mesh (linesurf::MeshValidity) as written by `evaluate` ("topology")
// and the `reconstruct` report ("validity"): one definition.

#include "linesurf/result.h"

#include <nlohmann/json.hpp>

namespace linesurf::cli {

nlohmann::json MeshValidityJson(const MeshValidity& v);

}  // namespace linesurf::cli
