#include "partition/voxel/plane_support.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "partition/voxel/active_blocks.h"
#include "partition/voxel/polygon_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace linesurf::partition {
namespace {

constexpr const char* kPlaneSupportStage = "plane_support";
constexpr int kMaxMarginBlocks = 64;

// Whether the segment meets `box` grown by `reach` on every axis (Liang-Barsky clipping).
bool SegmentMeetsGrownBox(const Segment3& segment, const Box3& box, double reach) {
  double t0 = 0.0;
  double t1 = 1.0;
  const Vec3 d = segment.p2 - segment.p1;
  for (int a = 0; a < 3; ++a) {
    const double lo = box.min[a] - reach - segment.p1[a];
    const double hi = box.max[a] + reach - segment.p1[a];
    if (d[a] == 0.0) {
      if (lo > 0.0 || hi < 0.0) return false;
      continue;
    }
    const double ta = lo / d[a];
    const double tb = hi / d[a];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
    if (t0 > t1) return false;
  }
  return true;
}

// The 26-neighbours of `crossed` (sorted) that some inlier comes within `reach` of.
std::vector<std::int64_t> NeighboursWithinReach(const BlockGrid& grid,
                                                std::span<const Segment3> segments,
                                                std::span<const SegmentId> inliers,
                                                std::span<const std::int64_t> crossed,
                                                double reach) {
  std::vector<std::int64_t> out;
  for (const SegmentId s : inliers) {
    const Segment3& segment = segments[s.index()];
    for (const Eigen::Vector3i& c : BlocksCrossed(grid, segment)) {
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
            if (!grid.IsInside(n)) continue;
            const std::int64_t linear = grid.LinearIndex(n);
            if (std::binary_search(crossed.begin(), crossed.end(), linear)) continue;
            if (SegmentMeetsGrownBox(segment, grid.BlockBox({0, n}), reach)) {
              out.push_back(linear);
            }
          }
        }
      }
    }
  }
  return out;
}

void SortUnique(std::vector<std::int64_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

std::vector<std::int64_t> RegionOf(const BlockGrid& grid,
                                   std::span<const Segment3> segments,
                                   const Plane3& plane,
                                   std::span<const SegmentId> inliers,
                                   double margin) {
  std::vector<std::int64_t> touched;
  for (const SegmentId s : inliers) {
    for (const Eigen::Vector3i& c : BlocksCrossed(grid, segments[s.index()])) {
      touched.push_back(grid.LinearIndex(c));
    }
  }
  if (inliers.size() >= 2) {
    const std::vector<std::int64_t> hull =
        BlocksMetByConvexPolygon(grid, InlierHull(plane, segments, inliers));
    touched.insert(touched.end(), hull.begin(), hull.end());
  }
  SortUnique(touched);
  const double whole = std::floor(margin);
  if (const double fraction = margin - whole; fraction > 0.0) {
    std::vector<std::int64_t> near =
        NeighboursWithinReach(grid, segments, inliers, touched, fraction * grid.block_size());
    touched.insert(touched.end(), near.begin(), near.end());
    SortUnique(touched);
  }
  return DilateBlocks(grid, touched, static_cast<int>(whole));
}

}  // namespace

Status PlaneSupportOptions::Validate() const {
  if (!(margin_blocks >= 0.0 && margin_blocks <= kMaxMarginBlocks)) {
    std::ostringstream message;
    message << "margin_blocks must be in [0, " << kMaxMarginBlocks << "], got " << margin_blocks;
    return Error{ErrorCode::kInvalidOptions, kPlaneSupportStage, message.str()};
  }
  return {};
}

PlaneSupportRegions RegionsFromBlockLists(std::vector<std::vector<std::int64_t>> plane_blocks) {
  PlaneSupportRegions out;
  std::vector<std::pair<std::int64_t, PlaneId>> pairs;  // (block, plane), to invert
  for (std::size_t p = 0; p < plane_blocks.size(); ++p) {
    out.plane_blocks.AddRow(plane_blocks[p]);
    for (const std::int64_t b : plane_blocks[p]) pairs.emplace_back(b, PlaneId(p));
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<PlaneId> row;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    row.push_back(pairs[i].second);
    if (i + 1 == pairs.size() || pairs[i + 1].first != pairs[i].first) {
      out.blocks.push_back(pairs[i].first);
      out.block_planes.AddRow(row);
      row.clear();
    }
  }
  return out;
}

Expected<PlaneSupportRegions> ComputePlaneSupport(const BlockGrid& grid,
                                                  std::span<const Segment3> segments,
                                                  std::span<const Plane3> planes,
                                                  std::span<const std::vector<SegmentId>> inliers,
                                                  const PlaneSupportOptions& options,
                                                  const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  return CatchAll(kPlaneSupportStage, [&]() -> PlaneSupportRegions {
    LINESURF_THROW_IF(planes.size() != inliers.size(),
                      kInvalidInput,
                      kPlaneSupportStage,
                      planes.size() << " planes but " << inliers.size() << " inlier lists");
    for (std::size_t p = 0; p < inliers.size(); ++p) {
      for (const SegmentId s : inliers[p]) {
        LINESURF_THROW_IF(!s.IsValid() || s.index() >= segments.size(),
                          kInvalidInput,
                          kPlaneSupportStage,
                          "plane " << p << ": inlier " << s.index() << " is not a segment (of "
                                   << segments.size() << ")");
      }
    }
    std::vector<std::vector<std::int64_t>> regions(inliers.size());
    RunInArena(ctx, [&] {
      tbb::parallel_for(std::size_t{0}, inliers.size(), [&](std::size_t p) {
        if (ctx.ShouldStop()) return;
        regions[p] = RegionOf(grid, segments, planes[p], inliers[p], options.margin_blocks);
      });
    });
    ctx.ThrowIfCancelled(kPlaneSupportStage);
    return RegionsFromBlockLists(std::move(regions));
  });
}

}  // namespace linesurf::partition
