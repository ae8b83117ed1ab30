#pragma once
/// @file public_vector.h
/// @brief The facade's plain Vector3 (linesurf/types.h) and the engine's Vec3, both ways.

#include "linesurf/types.h"

#include "engine/core/geometry.h"

namespace linesurf {

[[nodiscard]] inline Vec3 ToVec3(const Vector3& v) { return Vec3(v[0], v[1], v[2]); }
[[nodiscard]] inline Vector3 ToVector3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace linesurf
