#include "partition/arrangement/block_complexes.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "partition/arrangement/exact_predicates.h"
#include "partition/arrangement/seam_overlay.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

namespace linesurf::partition {
namespace {

constexpr char kBlockComplexesStage[] = "block_complexes";

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Eigen::Vector4d InputCoefficients(const Plane3& p) {
  return {p.normal.x(), p.normal.y(), p.normal.z(), p.Offset()};
}

/// The planes of each base block (increasing PlaneId), from the regions' block lists.
std::vector<std::vector<PlaneId>> PlanesPerBlock(const BlockGrid& grid,
                                                 std::size_t num_planes,
                                                 const PlaneSupportRegions& regions) {
  std::vector<std::vector<PlaneId>> out(static_cast<std::size_t>(grid.NumBaseBlocks()));
  for (std::size_t i = 0; i < regions.blocks.size(); ++i) {
    const std::int64_t b = regions.blocks[i];
    LINESURF_THROW_IF(b < 0 || b >= grid.NumBaseBlocks(),
                      kInvalidInput,
                      kBlockComplexesStage,
                      "support region block " << b << " is outside the grid");
    for (const PlaneId p : regions.block_planes[BlockId(i)]) {
      LINESURF_THROW_IF(p.index() >= num_planes,
                        kInvalidInput,
                        kBlockComplexesStage,
                        "support region names plane " << p.index() << " of " << num_planes);
      out[static_cast<std::size_t>(b)].push_back(p);
    }
  }
  return out;
}

/// Types the facets, maps sources to global ids, keys the planes, and records input planes
/// lying exactly on the block's faces.
void Finish(const BlockGrid& grid,
            const std::vector<Eigen::Vector4d>& coefficients,
            const std::vector<PlaneId>& planes,
            BlockComplex& block) {
  CellComplex& c = block.complex;
  for (std::size_t k = 0; k < c.planes.size(); ++k) {
    ComplexPlane& plane = c.planes[ComplexPlaneId(k)];
    if (k < kNumBoxPlanes) {
      block.plane_keys.push_back(BoxPlaneKey(block.base, static_cast<int>(k)));
    } else {
      plane.source = planes[plane.source.index()];
      block.plane_keys.push_back(PlaneKey::Input(plane.source));
    }
  }
  for (std::size_t k = 0; k < kNumBoxPlanes; ++k) {
    block.face_planes[k] = PlaneId();
    const Eigen::Vector4d& face = c.planes[ComplexPlaneId(k)].coefficients;
    for (const PlaneId p : planes) {
      if (ExactProportionality(coefficients[p.index()], face) != 0) {
        block.face_planes[k] = p;
        break;
      }
    }
  }
  for (std::size_t fi = 0; fi < c.NumFacets(); ++fi) {
    const std::size_t k = c.facet_plane[FacetId(fi)].index();
    FacetKind kind = FacetKind::kInterior;
    if (k < kNumBoxPlanes) {
      const int axis = static_cast<int>(k % 3);
      const bool on_box = k < 3 ? block.base[axis] == 0 : block.base[axis] == grid.dims()[axis] - 1;
      kind = on_box ? FacetKind::kSceneBoundary : FacetKind::kSeam;
    }
    block.facet_kind.push_back(kind);
  }
}

}  // namespace

std::vector<std::size_t> GlobalCellOffsets(const BlockComplexes& complexes) {
  std::vector<std::size_t> offsets(complexes.blocks.size() + 1, 0);
  for (std::size_t b = 0; b < complexes.blocks.size(); ++b) {
    offsets[b + 1] = offsets[b] + complexes.blocks[b].complex.NumCells();
  }
  return offsets;
}

std::vector<std::uint32_t> BlockOfEachCell(const BlockComplexes& complexes) {
  const std::vector<std::size_t> offsets = GlobalCellOffsets(complexes);
  std::vector<std::uint32_t> block_of_cell(offsets.back());
  for (std::size_t b = 0; b + 1 < offsets.size(); ++b) {
    std::fill(block_of_cell.begin() + static_cast<std::ptrdiff_t>(offsets[b]),
              block_of_cell.begin() + static_cast<std::ptrdiff_t>(offsets[b + 1]),
              static_cast<std::uint32_t>(b));
  }
  return block_of_cell;
}

Eigen::Vector4d BlockComplexes::Coefficients(PlaneKey key) const {
  if (!key.IsFace()) return plane_coefficients[key.plane().index()];
  Eigen::Vector4d out = Eigen::Vector4d::Zero();
  out[key.axis()] = 1.0;
  out[3] = -grid.FaceTable(key.axis())[static_cast<std::size_t>(key.face_index())];
  return out;
}

Expected<BlockComplexes> BuildBlockComplexes(const BlockGrid& grid,
                                             std::span<const Plane3> planes,
                                             const PlaneSupportRegions& regions,
                                             const CellComplexOptions& options,
                                             const RunContext& ctx) noexcept {
  if (Status ok = options.Validate(); !ok) return ok.error();
  return CatchAll(kBlockComplexesStage, [&]() -> BlockComplexes {
    auto start = std::chrono::steady_clock::now();
    BlockComplexes out{grid, {}, {}, {}, {}, {}};
    for (const Plane3& p : planes) out.plane_coefficients.push_back(InputCoefficients(p));
    const std::vector<std::vector<PlaneId>> per_block =
        PlanesPerBlock(grid, planes.size(), regions);
    const std::size_t n = per_block.size();
    std::vector<Box3> boxes(n);
    std::vector<std::vector<Plane3>> block_planes(n);
    for (std::size_t b = 0; b < n; ++b) {
      boxes[b] = grid.BlockBox({0, grid.BaseFromLinear(static_cast<std::int64_t>(b))});
      for (const PlaneId p : per_block[b]) block_planes[b].push_back(planes[p.index()]);
      out.stats.plane_block_pairs += per_block[b].size();
    }
    std::vector<CellComplexResult> built = [&] {
      Expected<std::vector<CellComplexResult>> r =
          BuildCellComplexes(boxes, block_planes, options, ctx);
      if (!r) throw LinesurfException(r.error());
      return std::move(r).value();
    }();
    out.blocks.resize(n);
    RunInArena(ctx, [&] {
      tbb::parallel_for(std::size_t{0}, n, [&](std::size_t b) {
        BlockComplex& block = out.blocks[b];
        block.base = grid.BaseFromLinear(static_cast<std::int64_t>(b));
        block.complex = std::move(built[b].complex);
        block.stats = built[b].stats;
        Finish(grid, out.plane_coefficients, per_block[b], block);
      });
    });
    for (const BlockComplex& block : out.blocks) {
      out.stats.cells += block.complex.NumCells();
      for (const PlaneId p : block.face_planes) out.stats.planes_on_faces += p.IsValid() ? 1 : 0;
    }
    out.stats.blocks = n;
    out.stats.seconds_complexes = SecondsSince(start);
    ctx.ThrowIfCancelled(kBlockComplexesStage);

    start = std::chrono::steady_clock::now();
    for (std::size_t b = 0; b < n; ++b) {
      for (int axis = 0; axis < 3; ++axis) {
        Eigen::Vector3i up = out.blocks[b].base;
        ++up[axis];
        if (!grid.IsInside(up)) continue;
        SeamFace face;
        face.axis = axis;
        face.lower_block = static_cast<std::uint32_t>(b);
        face.upper_block = static_cast<std::uint32_t>(grid.LinearIndex(up));
        out.seams.push_back(std::move(face));
      }
    }
    RunInArena(ctx, [&] {
      tbb::parallel_for(std::size_t{0}, out.seams.size(), [&](std::size_t s) {
        if (ctx.ShouldStop()) return;
        SeamFace& face = out.seams[s];
        const BlockComplex& lower = out.blocks[face.lower_block];
        const BlockComplex& upper = out.blocks[face.upper_block];
        face.facets = OverlayFace(out,
                                  BoxPlaneKey(lower.base, 3 + face.axis),
                                  FacePolygons(lower, 3 + face.axis),
                                  FacePolygons(upper, face.axis));
      });
    });
    ctx.ThrowIfCancelled(kBlockComplexesStage);
    out.stats.seam_faces = out.seams.size();
    for (const SeamFace& face : out.seams) out.stats.seam_facets += face.facets.size();
    out.stats.seconds_overlay = SecondsSince(start);
    return out;
  });
}

}  // namespace linesurf::partition
