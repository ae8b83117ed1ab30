// "room": the inside of a 6 x 5 x 2.8 m room with 0.3 m thick walls, floor and ceiling, a door
// niche and two window niches, a table (top slab on four legs standing on the floor), texture
// lines on the walls, floor and ceiling; viewpoints inside. The ground truth is the matter: the
// thick shell (outer box minus the room and niches) united with the table, one closed solid with
// an outer surface (normals outward) and an inner surface (normals into the room).

#include <algorithm>
#include <array>
#include <vector>

#include "tools/gen/family_layout.h"

namespace linesurf::synth {
namespace {

constexpr double kRoomWall = 0.3;
constexpr double kRoomX = 6.0;
constexpr double kRoomY = 5.0;
constexpr double kRoomZ = 2.8;

}  // namespace

FamilyLayout RoomLayout(const SynthSpec& /*spec*/) {
  FamilyLayout layout;
  layout.interior = true;
  const AxisBox outer{{-kRoomWall, -kRoomWall, -kRoomWall}, {kRoomX + kRoomWall, kRoomY + kRoomWall, kRoomZ + kRoomWall}};
  const AxisBox room{{0, 0, 0}, {kRoomX, kRoomY, kRoomZ}};
  const std::vector<AxisBox> cavities = {
      room,
      {{1.0, -0.2, 0.0}, {1.9, 0.0, 2.1}},  // door niche, south wall
      {{6.0, 1.5, 0.9}, {6.2, 3.5, 2.1}},   // window niche, east wall
      {{3.5, 5.0, 1.0}, {5.0, 5.2, 2.0}},   // window niche, north wall
  };
  std::vector<AxisBox> table = {{{2.0, 2.0, 0.70}, {3.6, 3.0, 0.78}}};  // top slab
  for (double x : {2.05, 3.47}) {
    for (double y : {2.05, 2.87}) table.push_back({{x, y, 0.0}, {x + 0.08, y + 0.08, 0.70}});
  }

  layout.solid.AddComponent(BoxesSolid(outer, cavities, table));
  layout.volume = outer.Volume();
  for (const AxisBox& b : cavities) layout.volume -= b.Volume();
  for (const AxisBox& b : table) layout.volume += b.Volume();

  // Texture lines (outward = into the room).
  AddTextureRectangle(layout, {0, 1.5, 1.2}, {0, 2.0, 0}, {0, 0, 0.8}, Vec3(1, 0, 0));  // painting
  AddTextureRectangle(layout, {3.0, 0, 1.0}, {1.5, 0, 0}, {0, 0, 1.0}, Vec3(0, 1, 0));  // poster
  AddTextureLine(layout, {0.2, kRoomY, 0.1}, {3.3, kRoomY, 0.1}, Vec3(0, -1, 0));      // skirting
  AddTextureLine(layout, {kRoomX, 0.2, 0.1}, {kRoomX, 4.8, 0.1}, Vec3(-1, 0, 0));      // skirting
  AddTextureRectangle(layout, {1.5, 1.3, 0}, {3.0, 0, 0}, {0, 2.4, 0}, Vec3(0, 0, 1));  // rug
  AddTextureRectangle(layout, {2.5, 2.0, kRoomZ}, {1.0, 0, 0}, {0, 1.0, 0}, Vec3(0, 0, -1));  // lamp

  for (double x : {1.0, 3.0, 5.0}) {
    for (double y : {1.0, 4.0}) layout.viewpoints.emplace_back(x, y, 1.6);
  }
  layout.viewpoints.emplace_back(0.8, 2.5, 1.6);
  layout.viewpoints.emplace_back(5.2, 2.5, 1.6);
  for (double x : {0.6, 5.4}) {
    for (double y : {0.6, 4.4}) layout.viewpoints.emplace_back(x, y, 0.4);  // low: under the table
  }
  layout.viewpoints.emplace_back(3.0, 0.7, 2.5);
  layout.viewpoints.emplace_back(3.0, 4.3, 2.5);

  layout.outliers.box.Extend(room.min);
  layout.outliers.box.Extend(room.max);
  layout.outliers.max_length = 1.0;
  return layout;
}

}  // namespace linesurf::synth
