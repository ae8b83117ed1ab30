#include "tools/gen/synthetic_files.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/io/mesh_io.h"
#include "engine/io/reference_json.h"
#include "tools/gen/synthesize.h"
#include "tools/gen/synthetic_meta.h"

#include <tbb/task_arena.h>

#include <array>
#include <utility>

namespace linesurf::synth {

SyntheticFiles::SyntheticFiles(std::unique_ptr<SyntheticScene> scene) noexcept
    : scene_(std::move(scene)) {}
SyntheticFiles::SyntheticFiles(SyntheticFiles&&) noexcept = default;
SyntheticFiles& SyntheticFiles::operator=(SyntheticFiles&&) noexcept = default;
SyntheticFiles::~SyntheticFiles() = default;

Expected<SyntheticFiles> SyntheticFiles::Generate(const SynthSpec& spec, int num_threads) noexcept {
  return CatchAll("synth", [&] {
    tbb::task_arena arena(ArenaConcurrency(num_threads));
    return SyntheticFiles(std::make_unique<SyntheticScene>(
        ValueOrThrow(arena.execute([&] { return Synthesize(spec); }))));
  });
}

Status SyntheticFiles::WriteLines(const std::filesystem::path& path) const noexcept {
  return io::WriteReferenceJson(scene_->scene, path);
}

Status SyntheticFiles::WriteGroundTruth(const std::filesystem::path& path) const noexcept {
  return io::WriteMesh(scene_->ground_truth, path);
}

Status SyntheticFiles::WriteMeta(const std::filesystem::path& path) const noexcept {
  return WriteSyntheticMeta(*scene_, path);
}

SyntheticSummary SyntheticFiles::Summary() const noexcept {
  SyntheticSummary summary;
  summary.segments = scene_->scene.segments.size();
  const std::array<std::size_t, 3> kinds = CountKinds(scene_->kinds);
  summary.structural = kinds[static_cast<std::size_t>(SegmentKind::kStructural)];
  summary.textural = kinds[static_cast<std::size_t>(SegmentKind::kTextural)];
  summary.outliers = kinds[static_cast<std::size_t>(SegmentKind::kOutlier)];
  summary.viewpoints = scene_->scene.viewpoints.size();
  summary.true_planes = scene_->true_planes.size();
  summary.ground_truth_faces = scene_->ground_truth.NumFaces();
  return summary;
}

}  // namespace linesurf::synth
