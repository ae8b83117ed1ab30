#include "engine/core/box_bvh.h"

#include "engine/core/rng.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace linesurf {
namespace {

/// 500 boxes of sides up to `side` in [-10, 10]^3: every third flat (a plane's outline), every
/// 50th empty.
std::vector<Box3> RandomBoxes(Rng& rng, double side) {
  std::vector<Box3> boxes;
  for (int i = 0; i < 500; ++i) {
    Box3 b;
    const Vec3 c(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(-10, 10));
    b.Extend(c);
    b.Extend(c + Vec3(rng.Uniform(0, side),
                      i % 3 == 0 ? 0.0 : rng.Uniform(0, side),
                      rng.Uniform(0, side)));
    boxes.push_back(i % 50 == 7 ? Box3{} : b);
  }
  return boxes;
}

/// The boxes a query reports (query(fn) calls fn per box), each checked to come once.
template <typename Query>
std::set<std::uint32_t> Reported(Query&& query) {
  std::set<std::uint32_t> met;
  EXPECT_FALSE(query([&](std::uint32_t i) {
    EXPECT_TRUE(met.insert(i).second) << "box " << i << " reported twice";
    return false;
  }));
  return met;
}

TEST(BoxBvh, ReportsExactlyTheBoxesARayMeets) {
  Rng rng(3);
  const std::vector<Box3> boxes = RandomBoxes(rng, 3.0);
  const BoxBvh bvh(boxes);
  // The 6 axis directions (zero components) and random ones.
  std::vector<Vec3> dirs = {
      Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  for (int i = 0; i < 50; ++i) {
    dirs.push_back(Vec3(rng.Normal(), rng.Normal(), rng.Normal()).normalized());
  }
  std::size_t total = 0;
  for (int r = 0; r < 40; ++r) {
    const Vec3 o(rng.Uniform(-12, 12), rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    for (const Vec3& d : dirs) {
      std::set<std::uint32_t> expected;
      for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        if (!boxes[i].IsEmpty() && BoxBvh::RayMeetsBox(o, d, boxes[i])) expected.insert(i);
      }
      EXPECT_EQ(Reported([&](auto&& fn) { return bvh.AnyAlongRay(o, d, fn); }), expected);
      total += expected.size();
    }
  }
  EXPECT_GT(total, 1000u);  // the rays do meet boxes
}

TEST(BoxBvh, ReportsExactlyTheBoxesASlabMeets) {
  Rng rng(5);
  const std::vector<Box3> boxes = RandomBoxes(rng, 2.0);
  const BoxBvh bvh(boxes);
  std::size_t total = 0;
  for (int k = 0; k < 60; ++k) {
    // Axis-aligned planes (zero normal components) and tilted ones, thin and thick slabs.
    const Vec3 normal = k < 6 ? Vec3::Unit(k % 3) : Vec3(rng.Normal(), rng.Normal(), rng.Normal());
    const Plane3 plane{Vec3(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(-10, 10)),
                       normal.normalized()};
    const double half_thickness = k % 2 == 0 ? 0.0 : rng.Uniform(0, 1);
    std::set<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      if (!boxes[i].IsEmpty() &&
          BoxMeetsSlab(boxes[i].Center(), 0.5 * boxes[i].Extent(), plane, half_thickness)) {
        expected.insert(i);
      }
    }
    EXPECT_EQ(Reported([&](auto&& fn) { return bvh.AnyInSlab(plane, half_thickness, fn); }),
              expected);
    EXPECT_LT(expected.size(), boxes.size());  // the slab leaves boxes out
    total += expected.size();
  }
  EXPECT_GT(total, 1000u);  // the slabs do meet boxes
}

TEST(BoxBvh, ReportsExactlyTheBoxesABoxOverlaps) {
  Rng rng(7);
  const std::vector<Box3> boxes = RandomBoxes(rng, 2.0);
  const BoxBvh bvh(boxes);
  std::size_t total = 0;
  for (int k = 0; k < 100; ++k) {
    // Query boxes of every size, some touching others exactly on a face (a box of the set).
    Box3 query = boxes[static_cast<std::size_t>(k) * 5];
    if (k % 2 == 1) {
      const Vec3 c(rng.Uniform(-12, 12), rng.Uniform(-12, 12), rng.Uniform(-12, 12));
      query = Box3{};
      query.Extend(c);
      query.Extend(c + Vec3(rng.Uniform(0, 4), rng.Uniform(0, 4), rng.Uniform(0, 4)));
    }
    std::set<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      const Box3& b = boxes[i];
      if (!b.IsEmpty() && !query.IsEmpty() && (query.min.array() <= b.max.array()).all() &&
          (b.min.array() <= query.max.array()).all()) {
        expected.insert(i);
      }
    }
    EXPECT_EQ(Reported([&](auto&& fn) { return bvh.AnyOverlapping(query, fn); }), expected);
    total += expected.size();
  }
  EXPECT_GT(total, 100u);  // the boxes do overlap
}

TEST(BoxBvh, RayMeetsBoxOnlyAheadAndOnItsBoundary) {
  Box3 b;
  b.Extend(Vec3(1, 0, 0));
  b.Extend(Vec3(2, 1, 1));
  EXPECT_TRUE(BoxBvh::RayMeetsBox(Vec3(0, 0.5, 0.5), Vec3::UnitX(), b));
  EXPECT_FALSE(BoxBvh::RayMeetsBox(Vec3(0, 0.5, 0.5), -Vec3::UnitX(), b));  // behind
  EXPECT_TRUE(BoxBvh::RayMeetsBox(Vec3(0, 1, 1), Vec3::UnitX(), b));        // along an edge
  EXPECT_FALSE(BoxBvh::RayMeetsBox(Vec3(0, 1.5, 0.5), Vec3::UnitX(), b));
  EXPECT_TRUE(BoxBvh::RayMeetsBox(Vec3(1.5, 0.5, 0.5), Vec3::UnitY(), b));  // from inside
}

TEST(BoxBvh, AnyAlongRayStopsAtTheFirstAcceptedBox) {
  std::vector<Box3> boxes(10);
  for (int i = 0; i < 10; ++i) {
    boxes[i].Extend(Vec3(i, 0, 0));
    boxes[i].Extend(Vec3(i + 0.5, 1, 1));
  }
  const BoxBvh bvh(boxes);
  int calls = 0;
  EXPECT_TRUE(bvh.AnyAlongRay(Vec3(-1, 0.5, 0.5), Vec3::UnitX(), [&](std::uint32_t) {
    ++calls;
    return true;
  }));
  EXPECT_EQ(calls, 1);
  EXPECT_FALSE(
      bvh.AnyAlongRay(Vec3(-1, 5, 0.5), Vec3::UnitX(), [](std::uint32_t) { return true; }));
  EXPECT_FALSE(
      BoxBvh(std::vector<Box3>{}).AnyAlongRay(Vec3::Zero(), Vec3::UnitX(), [](std::uint32_t) {
        return true;
      }));
}

}  // namespace
}  // namespace linesurf
