#include "tools/arrange/plane_arrangement.h"

#include "engine/core/exception.h"
#include "engine/core/geometry.h"
#include "engine/core/public_vector.h"
#include "engine/core/run_context.h"
#include "partition/arrangement/build_cell_complex.h"
#include "partition/arrangement/validate_cell_complex.h"
#include "partition/arrangement/write_cells_ply.h"

#include <utility>

namespace linesurf::arrange {

constexpr const char* kArrangeStage = "arrange";

struct PlaneArrangement::Impl {
  partition::CellComplexResult built;
  ArrangementCounts counts;
  Vec3 centre = Vec3::Zero();  ///< world position of the complex's origin
};

bool IsBox(const Vector3& box_min, const Vector3& box_max) noexcept {
  const Vec3 min = ToVec3(box_min);
  const Vec3 max = ToVec3(box_max);
  return min.allFinite() && max.allFinite() && (min.array() < max.array()).all();
}

Status ValidateCellsShrink(double shrink) noexcept {
  partition::CellsPlyOptions options;
  options.shrink = shrink;
  return options.Validate();
}

PlaneArrangement::PlaneArrangement(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
PlaneArrangement::PlaneArrangement(PlaneArrangement&&) noexcept = default;
PlaneArrangement& PlaneArrangement::operator=(PlaneArrangement&&) noexcept = default;
PlaneArrangement::~PlaneArrangement() = default;

Expected<PlaneArrangement> PlaneArrangement::Build(const Vector3& box_min,
                                                   const Vector3& box_max,
                                                   std::span<const Plane> planes,
                                                   const RunControl& control) noexcept {
  return CatchAll(kArrangeStage, [&] {
    LINESURF_THROW_IF(!IsBox(box_min, box_max), kInvalidInput, kArrangeStage,
                      "the box needs finite corners with min < max on every axis");
    Box3 world_box;
    world_box.min = ToVec3(box_min);
    world_box.max = ToVec3(box_max);
    auto impl = std::make_unique<Impl>();
    impl->centre = world_box.Center();
    const Box3 box{world_box.min - impl->centre, world_box.max - impl->centre};
    std::vector<Plane3> local;
    local.reserve(planes.size());
    for (const Plane& p : planes) local.push_back({ToVec3(p.point) - impl->centre, ToVec3(p.normal)});
    RunContext ctx;
    ctx.num_threads = 1;
    ctx.on_progress = control.on_progress;
    ctx.is_cancelled = control.is_cancelled;
    impl->built = ValueOrThrow(partition::BuildCellComplex(box, local, {}, ctx));
    const CellComplex& cx = impl->built.complex;
    const partition::CellComplexStats& s = impl->built.stats;
    impl->counts = {.cells = cx.NumCells(),
                    .facets = cx.NumFacets(),
                    .edges = cx.NumEdges(),
                    .vertices = cx.NumVertices(),
                    .planes_input = s.planes_input,
                    .planes_used = s.planes_used,
                    .planes_skipped_outside = s.planes_skipped_outside,
                    .planes_skipped_touching = s.planes_skipped_touching,
                    .planes_duplicate = s.planes_duplicate,
                    .planes_invalid = s.planes_invalid,
                    .exact_fallbacks = s.exact_fallbacks,
                    .seconds = s.seconds};
    return PlaneArrangement(std::move(impl));
  });
}

const ArrangementCounts& PlaneArrangement::Counts() const noexcept { return impl_->counts; }

const std::vector<std::string>& PlaneArrangement::Warnings() const noexcept {
  return impl_->built.warnings;
}

Status PlaneArrangement::Validate() const noexcept {
  return partition::ValidateCellComplex(impl_->built.complex);
}

Status PlaneArrangement::WriteCellsPly(const std::filesystem::path& path,
                                       double shrink) const noexcept {
  partition::CellsPlyOptions options;
  options.shrink = shrink;
  options.translation = impl_->centre;
  return partition::WriteCellsPly(impl_->built.complex, path, options);
}

}  // namespace linesurf::arrange
