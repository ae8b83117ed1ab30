// "floor": one storey of three rooms seen from inside: a 10 x 8 x 2.8 m floor plate with 0.3 m
// outer walls, floor and ceiling, 0.15 m inner walls with door openings between every two rooms,
// a window niche per room, texture on walls and floors; viewpoints in every room. The ground
// truth is the matter, as for "room": the thick shell minus the rooms, doors and niches.

#include "tools/gen/family_layout.h"

#include <vector>

namespace linesurf::synth {
namespace {

constexpr double kFloorWall = 0.3;
constexpr double kInner = 0.15;
constexpr double kX = 10.0;
constexpr double kY = 8.0;
constexpr double kZ = 2.8;
constexpr double kSplitX = 4.0;  // west room A: x in [0, 4]
constexpr double kSplitY = 4.0;  // east rooms B (south) and C (north) split at y = 4
constexpr double kDoorHeight = 2.1;

}  // namespace

FamilyLayout FloorLayout(const SynthSpec& /*spec*/) {
  FamilyLayout layout;
  layout.interior = true;
  const double xe = kSplitX + kInner;  // east rooms start here
  const double yn = kSplitY + kInner;  // north room starts here
  const AxisBox outer{{-kFloorWall, -kFloorWall, -kFloorWall}, {kX + kFloorWall, kY + kFloorWall, kZ + kFloorWall}};
  const std::vector<AxisBox> cavities = {
      {{0, 0, 0}, {kSplitX, kY, kZ}},               // A
      {{xe, 0, 0}, {kX, kSplitY, kZ}},              // B
      {{xe, yn, 0}, {kX, kY, kZ}},                  // C
      {{kSplitX, 1.0, 0}, {xe, 2.0, kDoorHeight}},  // door A-B
      {{kSplitX, 6.0, 0}, {xe, 7.0, kDoorHeight}},  // door A-C
      {{7.0, kSplitY, 0}, {8.0, yn, kDoorHeight}},  // door B-C
      {{-0.2, 3.0, 0.9}, {0, 5.0, 2.1}},            // window niche, A, west wall
      {{6.0, -0.2, 1.0}, {8.5, 0, 2.0}},            // window niche, B, south wall
      {{kX, 5.5, 1.0}, {kX + 0.2, 7.0, 2.0}},       // window niche, C, east wall
  };
  layout.solid.AddComponent(BoxesSolid(outer, cavities, {}));
  layout.volume = outer.Volume();
  for (const AxisBox& b : cavities) layout.volume -= b.Volume();

  // Texture (outward = into the rooms): paintings, skirting lines and rugs.
  AddTextureRectangle(layout, {0.5, kY, 1.2}, {2.0, 0, 0}, {0, 0, 0.8}, Vec3(0, -1, 0));
  AddTextureRectangle(layout, {kX, 1.0, 1.0}, {0, 2.0, 0}, {0, 0, 1.0}, Vec3(-1, 0, 0));
  AddTextureRectangle(layout, {5.0, kY, 1.3}, {1.2, 0, 0}, {0, 0, 0.7}, Vec3(0, -1, 0));
  AddTextureLine(layout, {0.2, 0, 0.1}, {3.8, 0, 0.1}, Vec3(0, 1, 0));
  AddTextureLine(layout, {xe, 0.2, 0.1}, {xe, 0.8, 0.1}, Vec3(1, 0, 0));
  AddTextureLine(layout, {xe + 0.2, kY, 0.1}, {kX - 0.2, kY, 0.1}, Vec3(0, -1, 0));
  AddTextureRectangle(layout, {0.8, 2.0, 0}, {2.4, 0, 0}, {0, 3.5, 0}, Vec3(0, 0, 1));
  AddTextureRectangle(layout, {5.5, 1.0, 0}, {3.0, 0, 0}, {0, 2.0, 0}, Vec3(0, 0, 1));
  AddTextureRectangle(layout, {5.5, 5.2, 0}, {3.0, 0, 0}, {0, 1.8, 0}, Vec3(0, 0, 1));

  // Per room: four at eye height, one high, one low in a corner.
  const std::vector<std::vector<Vec3>> rooms = {
      {{1.0, 2.0, 1.6},
       {3.0, 2.0, 1.6},
       {1.0, 6.0, 1.6},
       {3.0, 6.0, 1.6},
       {2.0, 4.0, 2.5},
       {0.5, 0.5, 0.4}},
      {{5.5, 1.0, 1.6},
       {8.5, 1.0, 1.6},
       {5.5, 3.0, 1.6},
       {8.5, 3.0, 1.6},
       {7.0, 2.0, 2.5},
       {9.5, 0.5, 0.4}},
      {{5.5, 5.5, 1.6},
       {8.5, 5.5, 1.6},
       {5.5, 7.5, 1.6},
       {8.5, 7.5, 1.6},
       {7.0, 6.0, 2.5},
       {9.5, 7.6, 0.4}},
  };
  for (const std::vector<Vec3>& room : rooms) {
    layout.viewpoints.insert(layout.viewpoints.end(), room.begin(), room.end());
  }
  layout.outliers.box.Extend(Vec3(0, 0, 0));
  layout.outliers.box.Extend(Vec3(kX, kY, kZ));
  layout.outliers.max_length = 1.0;
  return layout;
}

}  // namespace linesurf::synth
