#include "engine/pipeline/segment_evidence.h"

#include "engine/core/exception.h"
#include "engine/core/parallel.h"
#include "engine/core/vector_area.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <sstream>
#include <tuple>

namespace linesurf::pipeline {
namespace {

constexpr const char* kSegmentEvidenceStage = "evidence";
/// Segments per parallel work item (fixed, so chunking never depends on the thread count).
constexpr std::size_t kSegmentChunk = 32;
/// Sample points are moved off their plane(s) by this fraction of the box diagonal before
/// point location, so rounding of the projection cannot put them on the wrong side; the tie
/// directions passed to the locator settle points that still land exactly on a plane.
constexpr double kSideOffsetRelative = 1e-7;
/// A viewpoint closer to the segment's plane than this fraction of its distance to the sample
/// sees the plane edge-on: that sample carries no side information.
constexpr double kGrazingSine = 1e-6;
/// Segments shorter than this fraction of sigma after projection carry no primitive evidence.
constexpr double kMinProjectedLengthRelative = 1e-9;

std::int64_t ToFixed(double w) { return std::llround(w * kEvidenceFixedPointScale); }
double FromFixed(std::int64_t w) { return static_cast<double>(w) / kEvidenceFixedPointScale; }

void AtomicAdd(std::vector<std::int64_t>& v, std::size_t i, std::int64_t w) {
  std::atomic_ref<std::int64_t>(v[i]).fetch_add(w, std::memory_order_relaxed);
}

/// The group terms found in one chunk of segments.
struct ChunkGroups {
  std::vector<StructuralEntry> structural;
  std::vector<CreaseEntry> creases;
};

struct Accumulators {
  std::vector<std::int64_t> cost_if_empty;
  std::vector<std::int64_t> cost_if_full;
  std::vector<std::int64_t> facet_weight;
  std::vector<ChunkGroups> groups;  ///< per chunk
  std::atomic<std::size_t> samples{0}, outside{0}, grazing{0}, walks{0}, crossings{0},
      parallel_creases{0};
};

/// Parameters shared by every segment.
struct Context {
  const EvidenceSpace& space;
  const Scene& scene;
  const EnergyOptions& options;
  const IdVector<ViewpointId, CellId>& viewpoint_cells;
  double sigma = 1.0;
  double crease_weight = 0.0;
  double offset = 0.0;
  Accumulators& acc;
};

Vec3 ProjectOntoPlane(const Plane3& plane, const Vec3& p) {
  return p - plane.SignedDistance(p) * plane.normal;
}

/// Clips the sight segment from `v` to `target` to the box; returns the start point and its
/// cell, or an invalid cell when the segment misses the box.
std::pair<Vec3, CellId> SightStart(const Context& c, ViewpointId view, const Vec3& target) {
  const Vec3& v = c.scene.viewpoints[view];
  if (c.viewpoint_cells[view].IsValid()) return {v, c.viewpoint_cells[view]};
  const Vec3 d = target - v;
  double t0 = 0.0;
  double t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (v[a] < c.space.box().min[a] || v[a] > c.space.box().max[a]) return {v, CellId::Invalid()};
      continue;
    }
    double ta = (c.space.box().min[a] - v[a]) / d[a];
    double tb = (c.space.box().max[a] - v[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 >= t1) return {v, CellId::Invalid()};
  // Step a little inside so the start point is strictly in the box.
  const double t = std::min(t0 + 1e-9 * (t1 - t0) + c.offset / std::max(d.norm(), c.offset), t1);
  const Vec3 start = v + t * d;
  if (!c.space.box().Contains(start)) return {v, CellId::Invalid()};
  const std::array<Vec3, 1> ties{d};
  return {start, c.space.Locate(start, ties, CellId())};
}

/// Walks the sight ray from viewpoint `view` to `target` (in cell `target_cell`) and adds
/// `weight` to every facet crossed.
void AddSightRay(const Context& c,
                 ViewpointId view,
                 const Vec3& target,
                 CellId target_cell,
                 std::int64_t weight) {
  if (weight == 0 || !target_cell.IsValid()) return;
  const auto [start, start_cell] = SightStart(c, view, target);
  if (!start_cell.IsValid()) return;
  c.acc.walks.fetch_add(1, std::memory_order_relaxed);
  std::size_t crossed = 0;
  c.space.Walk(start, start_cell, target, target_cell, [&](std::size_t f) {
    AtomicAdd(c.acc.facet_weight, f, weight);
    ++crossed;
  });
  c.acc.crossings.fetch_add(crossed, std::memory_order_relaxed);
}

/// Counts `num_views` samples at `q`; false (and counted as outside) when q is off the box.
bool CountSample(const Context& c, const Vec3& q, std::size_t num_views) {
  c.acc.samples.fetch_add(num_views, std::memory_order_relaxed);
  if (c.space.box().Contains(q)) return true;
  c.acc.outside.fetch_add(num_views, std::memory_order_relaxed);
  return false;
}

std::int32_t NumSamples(const Context& c, double length) {
  const double k = std::ceil(c.options.samples_per_sigma * length / c.sigma);
  return static_cast<std::int32_t>(
      std::clamp(k, 1.0, static_cast<double>(c.options.max_samples_per_segment)));
}

/// Textural evidence and visibility of segment `s` projected onto `plane`.
void AddTextural(const Context& c, SegmentId s, const Plane3& plane, double length_fraction) {
  const Segment3& seg = c.scene.segments[s];
  const Vec3 a = ProjectOntoPlane(plane, seg.p1);
  const Vec3 b = ProjectOntoPlane(plane, seg.p2);
  const double length = (b - a).norm() * length_fraction;
  if (length <= kMinProjectedLengthRelative * c.sigma) return;
  const std::int32_t k_samples = NumSamples(c, length);
  const double per_sample = length / (k_samples * c.sigma);
  const std::int64_t w_tex = ToFixed(c.options.weights.textural * per_sample);
  const std::int64_t w_vis = ToFixed(c.options.weights.visibility * per_sample);
  const Vec3& n = plane.normal;
  const std::array<Vec3, 1> ties_plus{n};
  const std::array<Vec3, 1> ties_minus{-n};
  const auto views = c.scene.observations[s];
  CellId plus;
  CellId minus;
  for (std::int32_t k = 0; k < k_samples; ++k) {
    const Vec3 q = a + ((k + 0.5) / k_samples) * (b - a);
    if (!CountSample(c, q, views.size())) continue;
    const Vec3 q_plus = q + c.offset * n;
    const Vec3 q_minus = q - c.offset * n;
    // The previous sample's cells are close: start the location walk there.
    plus = c.space.Locate(q_plus, ties_plus, plus);
    minus = c.space.Locate(q_minus, ties_minus, minus);
    for (const ViewpointId v : views) {
      const Vec3 to_view = c.scene.viewpoints[v] - q;
      const double side = n.dot(to_view);
      if (std::abs(side) <= kGrazingSine * to_view.norm()) {
        c.acc.grazing.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      const bool view_on_plus = side > 0.0;
      const CellId behind = view_on_plus ? minus : plus;
      if (behind.IsValid() && w_tex != 0) AtomicAdd(c.acc.cost_if_empty, behind.index(), w_tex);
      AddSightRay(c, v, view_on_plus ? q_plus : q_minus, view_on_plus ? plus : minus, w_vis);
    }
  }
}

/// Structural evidence and visibility of segment `s` projected onto the crease p1 ∩ p2.
void AddStructural(
    const Context& c, SegmentId s, const Plane3& p1, const Plane3& p2, ChunkGroups& out) {
  const Segment3& seg = c.scene.segments[s];
  const Vec3& n1 = p1.normal;
  const Vec3& n2 = p2.normal;
  const double cos12 = n1.dot(n2);
  const double det = 1.0 - cos12 * cos12;
  const Vec3 u = n1.cross(n2).normalized();
  // Closest point of the crease to the segment's midpoint, then the endpoints projected on it.
  const Vec3 m = seg.Midpoint();
  const double r1 = p1.SignedDistance(m);
  const double r2 = p2.SignedDistance(m);
  const double g1 = (r1 - cos12 * r2) / det;
  const double g2 = (r2 - cos12 * r1) / det;
  const Vec3 x0 = m - g1 * n1 - g2 * n2;
  const Vec3 a = x0 + u * u.dot(seg.p1 - x0);
  const Vec3 b = x0 + u * u.dot(seg.p2 - x0);
  const double length = (b - a).norm();
  if (length <= kMinProjectedLengthRelative * c.sigma) return;
  // Dual basis of (n1, n2) in their span: n_i . m_j = delta_ij, so s1*m1 + s2*m2 points into
  // the quadrant (sign s1 of plane 1, sign s2 of plane 2).
  const Vec3 m1 = (n1 - cos12 * n2) / det;
  const Vec3 m2 = (n2 - cos12 * n1) / det;
  std::array<Vec3, 4> quadrant_dir;
  for (int qd = 0; qd < 4; ++qd) {
    const double s1 = (qd & 1) != 0 ? -1.0 : 1.0;
    const double s2 = (qd & 2) != 0 ? -1.0 : 1.0;
    quadrant_dir[qd] = (s1 * m1 + s2 * m2).normalized();
  }
  const std::int32_t k_samples = NumSamples(c, length);
  const double per_sample = length / (k_samples * c.sigma);
  const std::int64_t w_str = ToFixed(c.options.weights.structural * per_sample);
  const auto views = c.scene.observations[s];
  // Per segment, shared by its views: the crease is a property of the segment.
  const std::int64_t w_crease =
      views.empty() ? 0 : ToFixed(c.crease_weight * per_sample / views.size());
  const std::int64_t w_vis = ToFixed(c.options.weights.visibility * per_sample);
  std::array<CellId, 4> previous{};
  for (std::int32_t k = 0; k < k_samples; ++k) {
    const Vec3 q = a + ((k + 0.5) / k_samples) * (b - a);
    if (!CountSample(c, q, views.size())) continue;
    std::array<CellId, 4> cells{};
    std::array<Vec3, 4> points;
    for (int qd = 0; qd < 4; ++qd) {
      points[qd] = q + c.offset * quadrant_dir[qd];
      const std::array<Vec3, 2> ties{quadrant_dir[qd], u};
      cells[qd] = c.space.Locate(points[qd], ties, previous[qd]);
      previous[qd] = cells[qd];
    }
    for (const ViewpointId v : views) {
      const Vec3 to_view = c.scene.viewpoints[v] - q;
      const double t1 = n1.dot(to_view);
      const double t2 = n2.dot(to_view);
      const double grazing = kGrazingSine * to_view.norm();
      if (std::abs(t1) <= grazing && std::abs(t2) <= grazing) {
        c.acc.grazing.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      const int facing = (t1 < 0.0 ? 1 : 0) | (t2 < 0.0 ? 2 : 0);
      StructuralEntry entry;
      std::size_t count = 0;
      for (int qd = 0; qd < 4; ++qd) {
        const CellId cell = cells[qd];
        if (!cell.IsValid() || cell == cells[facing]) continue;
        if (std::find(entry.cells.begin(), entry.cells.begin() + count, cell) !=
            entry.cells.begin() + count) {
          continue;
        }
        entry.cells[count++] = cell;
      }
      if (count > 0 && w_str != 0) {
        // Insertion sort of at most three ids (std::sort here trips GCC 12's -Warray-bounds).
        for (std::size_t i = 1; i < count; ++i) {
          for (std::size_t j = i; j > 0 && entry.cells[j] < entry.cells[j - 1]; --j) {
            std::swap(entry.cells[j], entry.cells[j - 1]);
          }
        }
        entry.weight = w_str;
        out.structural.push_back(entry);
      }
      if (count == 3 && w_crease != 0 && cells[facing].IsValid()) {
        CreaseEntry crease{{cells[facing ^ 1], cells[facing ^ 2]}, cells[facing ^ 3], w_crease};
        if (crease.across[1] < crease.across[0]) std::swap(crease.across[0], crease.across[1]);
        out.creases.push_back(crease);
      }
      AddSightRay(c, v, points[facing], cells[facing], w_vis);
    }
  }
}

/// Visibility of a segment without planes: rays to the raw segment.
void AddVisibilityOnly(const Context& c, SegmentId s) {
  const Segment3& seg = c.scene.segments[s];
  const double length = seg.Length();
  if (length <= 0.0) return;
  const std::int32_t k_samples = NumSamples(c, length);
  const std::int64_t w_vis = ToFixed(c.options.weights.visibility * length / (k_samples * c.sigma));
  const auto views = c.scene.observations[s];
  CellId hint;
  for (std::int32_t k = 0; k < k_samples; ++k) {
    const Vec3 q = seg.p1 + ((k + 0.5) / k_samples) * (seg.p2 - seg.p1);
    if (!CountSample(c, q, views.size())) continue;
    for (const ViewpointId v : views) {
      const std::array<Vec3, 1> ties{c.scene.viewpoints[v] - q};
      hint = c.space.Locate(q, ties, hint);
      AddSightRay(c, v, q, hint, w_vis);
    }
  }
}

void ProcessSegment(const Context& c, SegmentId s, ChunkGroups& groups) {
  const PlaneMembership membership =
      c.scene.HasMemberships() ? c.scene.memberships[s] : PlaneMembership{};
  if (membership.count == 0) {
    AddVisibilityOnly(c, s);
    return;
  }
  const Plane3& p1 = c.scene.planes[membership.planes[0]];
  if (membership.count == 1) {
    AddTextural(c, s, p1, 1.0);
    return;
  }
  const Plane3& p2 = c.scene.planes[membership.planes[1]];
  const double sin_angle = p1.normal.cross(p2.normal).norm();
  const double min_sin = std::sin(c.options.min_crease_angle_deg * std::numbers::pi / 180.0);
  if (sin_angle < min_sin || sin_angle == 0.0) {
    c.acc.parallel_creases.fetch_add(1, std::memory_order_relaxed);
    const Segment3& seg = c.scene.segments[s];
    const double d1 = std::abs(p1.SignedDistance(seg.p1)) + std::abs(p1.SignedDistance(seg.p2));
    const double d2 = std::abs(p2.SignedDistance(seg.p1)) + std::abs(p2.SignedDistance(seg.p2));
    AddTextural(c, s, d2 < d1 ? p2 : p1, 1.0);
    return;
  }
  if (c.options.structural_as_textural) {
    AddTextural(c, s, p1, 1.0);
    AddTextural(c, s, p2, 1.0);
    return;
  }
  AddStructural(c, s, p1, p2, groups);
}

/// The entries of every chunk's `member`, sorted by `key` and with identical keys merged. The
/// sort is parallel and unstable, but merged weights are integer sums, so the order of addition
/// does not matter.
template <typename Entry, typename Key>
std::vector<Entry> MergeChunks(std::vector<ChunkGroups>& chunks,
                               std::vector<Entry> ChunkGroups::*member,
                               Key key,
                               const RunContext& ctx) {
  std::vector<Entry> all;
  for (ChunkGroups& chunk : chunks) {
    all.insert(all.end(), (chunk.*member).begin(), (chunk.*member).end());
    std::vector<Entry>().swap(chunk.*member);
  }
  RunInArena(ctx, [&] {
    tbb::parallel_sort(
        all.begin(), all.end(), [&](const Entry& x, const Entry& y) { return key(x) < key(y); });
  });
  std::vector<Entry> merged;
  for (std::size_t i = 0; i < all.size();) {
    Entry sum = all[i];
    std::size_t j = i + 1;
    for (; j < all.size() && key(all[j]) == key(all[i]); ++j) sum.weight += all[j].weight;
    merged.push_back(sum);
    i = j;
  }
  return merged;
}

}  // namespace

void CheckEvidenceInput(const Scene& scene,
                        const Box3& box,
                        const EnergyOptions& options,
                        EvidenceStats& stats) {
  if (const Status st = options.Validate(); !st) throw LinesurfException(st.error());
  LINESURF_THROW_IF(scene.HasMemberships() && scene.memberships.size() != scene.NumSegments(),
                    kInvalidInput,
                    kSegmentEvidenceStage,
                    "memberships has " << scene.memberships.size() << " entries for "
                                       << scene.NumSegments() << " segments");
  LINESURF_THROW_IF(scene.observations.NumRows() != scene.NumSegments(),
                    kInvalidInput,
                    kSegmentEvidenceStage,
                    "observations has " << scene.observations.NumRows() << " rows for "
                                        << scene.NumSegments() << " segments");
  for (std::size_t s = 0; s < scene.NumSegments(); ++s) {
    const SegmentId id(s);
    const std::uint8_t count = scene.HasMemberships() ? scene.memberships[id].count : 0;
    LINESURF_THROW_IF(count > 2,
                      kInvalidInput,
                      kSegmentEvidenceStage,
                      "segment " << s << " has " << count << " planes");
    for (std::uint8_t k = 0; k < count; ++k) {
      LINESURF_THROW_IF(scene.memberships[id].planes[k].index() >= scene.planes.size(),
                        kInvalidInput,
                        kSegmentEvidenceStage,
                        "segment " << s << ": plane index out of range");
    }
    ++stats.segments_with_planes[count];
    stats.observations += scene.observations[id].size();
  }
  for (const ViewpointId v : scene.observations.items()) {
    LINESURF_THROW_IF(v.index() >= scene.viewpoints.size(),
                      kInvalidInput,
                      kSegmentEvidenceStage,
                      "observation of viewpoint " << v.index() << " out of range");
  }
  stats.sigma = options.sigma ? *options.sigma : DefaultSigma(scene);
  if (Status scale = CheckEnergyScale(scene, box, options); !scale) {
    throw LinesurfException(scale.error());
  }
}

IntegratedEvidence IntegrateSegments(const EvidenceSpace& space,
                                     const Scene& scene,
                                     const EnergyOptions& options,
                                     BoundaryMode boundary,
                                     EvidenceStats& stats,
                                     const RunContext& ctx) {
  stats.crease_weight = CreaseWeight(options, boundary);
  Accumulators acc;
  acc.cost_if_empty.assign(space.NumCells(), 0);
  acc.cost_if_full.assign(space.NumCells(), 0);
  acc.facet_weight.assign(space.NumFacets(), 0);
  const std::size_t num_chunks = (scene.NumSegments() + kSegmentChunk - 1) / kSegmentChunk;
  acc.groups.resize(num_chunks);
  IdVector<ViewpointId, CellId> viewpoint_cells(scene.viewpoints.size(), CellId::Invalid());
  const Box3& box = space.box();
  const Context c{space,
                  scene,
                  options,
                  viewpoint_cells,
                  stats.sigma,
                  stats.crease_weight,
                  kSideOffsetRelative * box.Extent().norm(),
                  acc};
  std::atomic<bool> stopped{false};
  std::atomic<std::size_t> done{0};
  RunInArena(ctx, [&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, scene.viewpoints.size(), 64),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t v = r.begin(); v != r.end(); ++v) {
            const Vec3& p = scene.viewpoints[ViewpointId(v)];
            if (box.Contains(p)) viewpoint_cells[ViewpointId(v)] = space.Locate(p, {}, CellId());
          }
        },
        tbb::simple_partitioner{});
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, num_chunks, 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t chunk = r.begin(); chunk != r.end(); ++chunk) {
            if (stopped.load(std::memory_order_relaxed) || ctx.ShouldStop()) {
              stopped.store(true, std::memory_order_relaxed);
              return;
            }
            const std::size_t end = std::min(scene.NumSegments(), (chunk + 1) * kSegmentChunk);
            for (std::size_t s = chunk * kSegmentChunk; s < end; ++s) {
              ProcessSegment(c, SegmentId(s), acc.groups[chunk]);
            }
            const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
            ctx.ReportProgress(kSegmentEvidenceStage,
                               static_cast<double>(finished) / static_cast<double>(num_chunks));
          }
        },
        tbb::simple_partitioner{});
  });
  LINESURF_THROW_IF(stopped.load(), kCancelled, kSegmentEvidenceStage, "cancelled");

  // Viewpoint prior, per observation.
  const std::int64_t w_prior = ToFixed(options.weights.viewpoint_prior);
  for (const ViewpointId v : scene.observations.items()) {
    const CellId cell = viewpoint_cells[v];
    if (cell.IsValid()) {
      acc.cost_if_full[cell.index()] += w_prior;
    } else {
      ++stats.viewpoints_outside_box;
    }
  }
  stats.samples = acc.samples.load();
  stats.samples_outside_box = acc.outside.load();
  stats.grazing_samples = acc.grazing.load();
  stats.walks = acc.walks.load();
  stats.facets_crossed = acc.crossings.load();
  stats.parallel_creases = acc.parallel_creases.load();

  IntegratedEvidence out;
  out.structural = MergeChunks(
      acc.groups, &ChunkGroups::structural, [](const StructuralEntry& e) { return e.cells; }, ctx);
  out.creases = MergeChunks(
      acc.groups,
      &ChunkGroups::creases,
      [](const CreaseEntry& e) { return std::make_tuple(e.across[0], e.across[1], e.opposite); },
      ctx);
  out.cost_if_empty = std::move(acc.cost_if_empty);
  out.cost_if_full = std::move(acc.cost_if_full);
  out.facet_weight = std::move(acc.facet_weight);
  out.viewpoint_cells = std::move(viewpoint_cells);
  return out;
}

void AddIntegratedTerms(const EvidenceSpace& space,
                        const IntegratedEvidence& evidence,
                        const EnergyOptions& options,
                        double sigma,
                        solver::EnergyInput& energy) {
  energy.ResizeCells(space.NumCells());
  for (std::size_t i = 0; i < space.NumCells(); ++i) {
    energy.cost_if_empty[CellId(i)] = FromFixed(evidence.cost_if_empty[i]);
    energy.cost_if_full[CellId(i)] = FromFixed(evidence.cost_if_full[i]);
  }
  const double area_scale = options.weights.area / (sigma * sigma);
  for (std::size_t f = 0; f < space.NumFacets(); ++f) {
    const auto [a, b] = space.FacetCells(f);
    if (!a.IsValid() || !b.IsValid()) continue;
    double weight = FromFixed(evidence.facet_weight[f]);
    if (area_scale > 0.0) weight += area_scale * space.FacetArea(f);
    if (weight > 0.0) energy.AddPair(a, b, weight);
  }
  std::vector<CellId> group;
  for (const StructuralEntry& entry : evidence.structural) {
    group.clear();
    for (const CellId cell : entry.cells) {
      if (cell.IsValid()) group.push_back(cell);
    }
    energy.AddStructuralGroup(group, FromFixed(entry.weight));
  }
  constexpr std::array<std::int8_t, 3> kCreaseSigns{1, 1, -1};
  for (const CreaseEntry& entry : evidence.creases) {
    const double weight = FromFixed(entry.weight);
    const auto [a, b] = entry.across;
    const std::array<CellId, 3> a_first{a, entry.opposite, b};
    const std::array<CellId, 3> b_first{b, entry.opposite, a};
    energy.AddParityGroup(a_first, kCreaseSigns, 0.5 * weight, -1);
    energy.AddParityGroup(b_first, kCreaseSigns, 0.5 * weight, -1);
    energy.cost_if_empty[entry.opposite] -= weight;
  }
}

double PolygonArea(std::span<const Vec3> points) { return 0.5 * TwiceVectorArea(points).norm(); }

double FacetArea(const CellComplex& cx, FacetId f) {
  std::vector<Vec3> points;
  for (const VertexId v : cx.facet_vertices[f]) points.push_back(cx.vertex_points[v]);
  return PolygonArea(points);
}

std::vector<std::string> EvidenceWarnings(const EvidenceStats& stats) {
  std::vector<std::string> warnings;
  const auto warn = [&](std::size_t n, const char* what) {
    if (n == 0) return;
    std::ostringstream os;
    os << n << " " << what;
    warnings.push_back(os.str());
  };
  warn(stats.parallel_creases,
       "structural segments with nearly parallel planes treated as textural");
  warn(stats.samples_outside_box, "segment samples outside the box skipped");
  warn(stats.viewpoints_outside_box, "observations from viewpoints outside the box: no prior");
  warn(stats.grazing_samples,
       "segment samples skipped: the viewpoint lies in the segment's plane (no evidence)");
  return warnings;
}

}  // namespace linesurf::pipeline
