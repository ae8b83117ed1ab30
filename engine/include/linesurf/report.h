#pragma once
/// @file report.h
/// @brief Run reports as JSON text, one layout for every front end: `linesurf reconstruct
/// --report` and `detect --report` write these (adding the paths they read and wrote), Python's
/// `result["report"]` is this JSON parsed, the C API returns it
/// (docs/design/options_and_reports.md). Each throws std::bad_alloc only.

#include "linesurf/export.h"
#include "linesurf/options.h"
#include "linesurf/result.h"

#include <string>

namespace linesurf {
inline namespace v3 {

/// stats_version (the stats' layout_version), options (by path, nested), then each stage struct
/// of the stats under the keys of linesurf 1's report: counts, block and scene decisions, eps,
/// solver, mesh, quality figures when measured, stage times and peak memory; the mesh's validity
/// (CheckMesh) and the warnings.
[[nodiscard]] LINESURF_API std::string ReportJson(const ReconstructResult& result,
                                                  const ReconstructOptions& options);
/// Options, detection stats and every plane's inlier count and length (plane i of `planes`).
[[nodiscard]] LINESURF_API std::string ReportJson(const DetectResult& result,
                                                  const DetectOptions& options);
/// The classes of CheckMesh.
[[nodiscard]] LINESURF_API std::string ReportJson(const MeshValidity& validity);
/// The figures without ground truth; components beyond the first 200 are counted, not listed.
[[nodiscard]] LINESURF_API std::string ReportJson(const SurfaceQuality& quality);

}  // namespace v3
}  // namespace linesurf
