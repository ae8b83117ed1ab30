#pragma once
// Internal: what each synthetic family contributes (solid, texture lines, viewpoints, regions);
// synthesize.cpp turns a layout into segments with cuts, trims, visibility, noise and outliers.

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/rng.h"
#include "engine/core/scene.h"
#include "tools/gen/solid_model.h"
#include "tools/gen/synthesize.h"

namespace linesurf::synth {

/// Random stream families (second argument of MixSeed after the stage): one stream per item.
enum class SynthStream : std::uint64_t {
  kLayout = 1,   ///< per building (city) or per family-level choice
  kCut = 2,      ///< per true line: over-segmentation and trimming
  kNoise = 3,    ///< per visible piece
  kOutlier = 4,  ///< per outlier
  kSplit = 5,    ///< per observation of the residual split
};

/// Rng for item `index` of `stream` under `seed`.
inline Rng StreamRng(std::uint64_t seed, SynthStream stream, std::uint64_t index) {
  return Rng(MixSeed(seed, RngStage::kSynth, static_cast<std::uint64_t>(stream), index));
}

/// A line drawn on the ground truth before cutting: on a sharp edge or on a face.
struct TrueLine {
  Segment3 segment;
  SegmentKind kind = SegmentKind::kTextural;
  PlaneMembership planes;
  /// Outward normals of the faces the line lies on (planes.count of them): a viewpoint must be
  /// in front of at least one to see the line.
  std::array<Vec3, 2> outward{Vec3::Zero(), Vec3::Zero()};
};

/// Where outliers are drawn.
struct OutlierRegion {
  bool ball = false;           ///< true: both endpoints uniform in the ball; false: box + length
  Vec3 centre = Vec3::Zero();  ///< ball centre
  double radius = 0.0;         ///< ball radius, metres
  Box3 box;                    ///< first endpoint uniform in the box
  double min_length = 0.2;     ///< box outliers: length uniform in [min_length, max_length]
  double max_length = 2.0;
};

struct FamilyLayout {
  SolidModel solid;
  std::vector<TrueLine> texture_lines;  ///< structural lines come from solid.SharpEdges()
  std::vector<Vec3> viewpoints;
  bool interior = false;
  double volume = 0.0;  ///< analytic volume of the solid
  /// Viewpoints farther than this from a segment's midpoint are not considered (metres).
  double max_view_distance = std::numeric_limits<double>::infinity();
  OutlierRegion outliers;
  int default_max_pieces = 3;
  double default_max_trim = 0.1;
  /// Cutting never makes pieces shorter than this (metres), before trimming.
  double min_piece_length = 0.3;
};

/// Adds a textural line on the face of plane (outward, point_on_face).
void AddTextureLine(FamilyLayout& layout, const Vec3& a, const Vec3& b, const Vec3& outward);
/// Adds the 4 sides of the rectangle corner, corner + u, corner + u + v, corner + v on a face.
void AddTextureRectangle(FamilyLayout& layout, const Vec3& corner, const Vec3& u, const Vec3& v,
                         const Vec3& outward);
/// Adds facade texture on every vertical face of `component` whose bottom edge lies on z = 0:
/// floor bands every `storey` metres and ground-floor window rectangles.
void AddFacadeTexture(FamilyLayout& layout, const SolidComponent& component, double storey);

/// Adds `count` viewpoints evenly on the horizontal circle of `radius` about the z axis at
/// `height` (half a step off the +x axis).
void AddViewRing(FamilyLayout& layout, int count, double radius, double height);

/// Number of buildings of the city family (spec.size, or its default).
int CityBuildingCount(const SynthSpec& spec);

FamilyLayout CubeLayout(const SynthSpec& spec);
FamilyLayout HouseLayout(const SynthSpec& spec);
FamilyLayout RoomLayout(const SynthSpec& spec);
FamilyLayout LShapeLayout(const SynthSpec& spec);
FamilyLayout FloorLayout(const SynthSpec& spec);
FamilyLayout CityLayout(const SynthSpec& spec);

}  // namespace linesurf::synth
