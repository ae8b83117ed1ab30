#pragma once
// Line3D++ text output (docs/user/formats.md; Line3D++ README, reference official-impl.md section 1.1).

#include <filesystem>

#include "engine/core/scene.h"
#include "engine/io/camera_centres.h"

namespace linesurf::io {

/// Reads a Line3D++ .txt: one text line per cluster, `n` then n segments (6 numbers), `m` then m
/// observations `cam_id seg_id u1 v1 u2 v2`. Every segment of a cluster becomes one scene segment
/// carrying all the cluster's observations: viewpoint = centres[cam_id], residual = (u1,v1,u2,v2)
/// kept at full precision; seg_id is dropped. Throws kInvalidInput naming the file and line.
Scene ReadLine3dpp(const std::filesystem::path& path, const CameraCentres& centres);

}  // namespace linesurf::io
