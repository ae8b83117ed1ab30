#pragma once
// The stage name and the angle conversion shared by the files of plane detection (internal to
// engine/detect).

#include <numbers>

namespace linesurf::detect {

/// Stage of the errors, progress and cancellation of plane detection.
inline constexpr char kDetectPlanesStage[] = "detect_planes";

inline double DegToRad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace linesurf::detect
