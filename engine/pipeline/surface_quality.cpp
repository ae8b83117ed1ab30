#include "engine/pipeline/surface_quality.h"

#include "linesurf/option_schema.h"

#include "engine/core/box_bvh.h"
#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/median_segment_length.h"
#include "engine/core/parallel.h"
#include "engine/detect/collinear_groups.h"
#include "partition/mesh/triangle_tree.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

namespace linesurf::pipeline {
namespace {

constexpr const char* kSurfaceQualityStage = "surface_quality";
/// Segments per parallel task; fixed so the chunking never depends on the thread count.
constexpr std::size_t kSegmentGrain = 64;
/// Planes per parallel task of the off-surface search.
constexpr std::size_t kPlaneGrain = 16;
/// Parts of one line: every endpoint within this fraction of the median segment length of the
/// other's line (as eps auto counts them).
constexpr double kCollinearPartsOverMedianLength = 1e-5;

/// A component of the mesh: faces sharing a vertex (FaceComponents).
struct ComponentTag {};
using ComponentId = StrongId<ComponentTag>;

/// The mesh's faces fanned into a triangle tree, with the component of every face.
struct MeshIndex {
  partition::TriangleTree tree;
  std::vector<std::uint32_t> face_component;
  std::size_t num_components = 0;
};

/// Components: faces sharing a vertex, vertices at the bit-identical position being one.
std::vector<std::uint32_t> FaceComponents(const PolygonMesh& mesh, std::size_t& count) {
  const std::size_t nv = mesh.vertices.size();
  DisjointSets sets(nv);
  std::vector<std::size_t> order(nv);
  std::iota(order.begin(), order.end(), 0);
  const auto key = [&](std::size_t i) {
    const Vec3& p = mesh.vertices[i];
    return std::make_tuple(p.x(), p.y(), p.z());
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_pair(key(a), a) < std::make_pair(key(b), b);
  });
  for (std::size_t k = 1; k < nv; ++k) {
    if (key(order[k]) == key(order[k - 1])) sets.Union(order[k], order[k - 1]);
  }
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    for (std::size_t k = 1; k < face.size(); ++k) sets.Union(face[0], face[k]);
  }
  // Number components by their first face.
  std::vector<ComponentId> id_of_root(nv);
  std::vector<std::uint32_t> out(mesh.NumFaces());
  count = 0;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const std::size_t root = sets.Find(mesh.Face(f)[0]);
    if (!id_of_root[root].IsValid()) id_of_root[root] = ComponentId(count++);
    out[f] = id_of_root[root].value();
  }
  return out;
}

MeshIndex IndexMesh(const PolygonMesh& mesh) {
  MeshIndex index{partition::TriangleTree(mesh, kSurfaceQualityStage, "surface"), {}, 0};
  index.face_component = FaceComponents(mesh, index.num_components);
  return index;
}

/// What one segment contributes; summed over segments in id order.
struct SegmentFigures {
  double near_length = 0.0;
  /// (component, sample length within the fit distance), one entry per near sample.
  std::vector<std::pair<std::uint32_t, double>> near_by_component;
  double sight_length = 0.0;
  double clear_length = 0.0;
  /// The components of every near sample's nearest face and of every face a sight ray meets,
  /// sorted and unique, when asked for: the figures stay those of a surface without any other.
  std::vector<std::uint32_t> components;
};

/// The sight ray eye -> p is clear unless it crosses a face whose plane lies farther than `fit`
/// from p: a face the sample lies on (within the noise) does not hide it, even when a grazing ray
/// meets that face well before the noisy sample.
bool IsClear(const Vec3& eye,
             const Vec3& p,
             const partition::TriangleTree& tree,
             double fit,
             std::vector<std::uint32_t>& hits) {
  tree.IntersectedTriangles(eye, p, hits);
  for (const std::uint32_t t : hits) {
    const auto [a, b, c] = tree.Corners(t);
    const Vec3 n = (b - a).cross(c - a).normalized();
    if (std::abs(n.dot(p - a)) > fit) return false;
  }
  return true;
}

SegmentFigures MeasureSegment(const Scene& scene,
                              SegmentId s,
                              bool supported,
                              const MeshIndex& index,
                              double fit,
                              int samples,
                              bool list_components) {
  SegmentFigures out;
  const Segment3& seg = scene.segments[s];
  const double piece = seg.Length() / samples;
  const partition::TriangleTree& tree = index.tree;
  std::vector<std::uint32_t> hits;
  for (int k = 0; k < samples; ++k) {
    const Vec3 p = seg.p1 + ((k + 0.5) / samples) * (seg.p2 - seg.p1);
    if (supported) {
      const partition::TriangleTree::Nearest nearest = tree.Closest(p);
      if (nearest.squared_distance <= fit * fit) {
        out.near_length += piece;
        out.near_by_component.emplace_back(index.face_component[tree.FaceOf(nearest.triangle)],
                                           piece);
      }
    }
    for (ViewpointId v : scene.observations[s]) {
      out.sight_length += piece;
      if (IsClear(scene.viewpoints[v], p, tree, fit, hits)) out.clear_length += piece;
      if (!list_components) continue;
      for (const std::uint32_t t : hits)
        out.components.push_back(index.face_component[tree.FaceOf(t)]);
    }
  }
  if (list_components) {
    for (const auto& [c, length] : out.near_by_component) out.components.push_back(c);
    std::sort(out.components.begin(), out.components.end());
    out.components.erase(std::unique(out.components.begin(), out.components.end()),
                         out.components.end());
  }
  return out;
}

/// The distinct line of every segment: the parts of one line (a residual split: exactly
/// collinear) share one id.
std::vector<std::uint32_t> LineOfSegment(const Scene& scene) {
  std::vector<std::uint32_t> line(scene.NumSegments(), 0);
  const double length = MedianSegmentLength(scene);
  if (!(length > 0.0)) return line;
  const detect::CollinearGroups groups = detect::GroupCollinearSegments(
      scene.segments.raw(), kCollinearPartsOverMedianLength * length);
  for (std::size_t g = 0; g < groups.members.NumRows(); ++g) {
    for (SegmentId s : groups.members[SegmentId(g)])
      line[s.index()] = static_cast<std::uint32_t>(g);
  }
  return line;
}

/// The planes on which no face lies (every corner within eps), in parallel over the planes. Each
/// plane asks a box hierarchy of the faces for those near its slab and stops at the first one on
/// it, where testing every face against every plane was quadratic in the scene.
std::vector<std::uint32_t> PlanesOffSurface(const PolygonMesh& mesh,
                                            const Scene& scene,
                                            double eps) {
  std::vector<Box3> boxes(mesh.NumFaces());
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    if (face.size() < 3) continue;  // empty box: never met
    for (std::uint32_t v : face) boxes[f].Extend(mesh.vertices[v]);
  }
  const BoxBvh faces(boxes);
  std::vector<char> on(scene.planes.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, on.size(), kPlaneGrain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t p = range.begin(); p < range.end(); ++p) {
                        const Plane3& plane = scene.planes.raw()[p];
                        // Twice eps for the boxes: a rounding never prunes a face within eps.
                        on[p] = faces.AnyInSlab(plane, 2.0 * eps, [&](std::uint32_t f) {
                          const auto face = mesh.Face(f);
                          return std::all_of(face.begin(), face.end(), [&](std::uint32_t v) {
                            return std::abs(plane.SignedDistance(mesh.vertices[v])) <= eps;
                          });
                        });
                      }
                    });
  std::vector<std::uint32_t> off;
  for (std::size_t p = 0; p < on.size(); ++p) {
    if (on[p] == 0) off.push_back(static_cast<std::uint32_t>(p));
  }
  return off;
}

double FaceVolume(const PolygonMesh& mesh, std::size_t f) {
  const auto face = mesh.Face(f);
  double v = 0.0;
  for (std::size_t k = 1; k + 1 < face.size(); ++k) {
    const Vec3& a = mesh.vertices[face[0]];
    v += a.dot(mesh.vertices[face[k]].cross(mesh.vertices[face[k + 1]])) / 6.0;
  }
  return v;
}

void ThrowIfMembershipsMismatch(const Scene& scene) {
  LINESURF_THROW_IF(
      scene.HasMemberships() && scene.memberships.size() != scene.NumSegments(),
      kInvalidInput,
      kSurfaceQualityStage,
      "memberships: " << scene.memberships.size() << " for " << scene.NumSegments() << " segments");
}

bool IsSupported(const Scene& scene, SegmentId s) {
  return scene.HasMemberships() && scene.memberships[s].count > 0;
}

/// Measures, in parallel, the segments i for which `measure(i)` holds into per_segment[i].
template <typename Pred>
void MeasureSegments(const Scene& scene,
                     const MeshIndex& index,
                     const SurfaceQualityOptions& options,
                     double fit,
                     bool list_components,
                     const RunContext& ctx,
                     Pred&& measure,
                     std::vector<SegmentFigures>& per_segment) {
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, scene.NumSegments(), kSegmentGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (ctx.ShouldStop()) return;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          if (!measure(i)) continue;
          const SegmentId s(static_cast<std::uint32_t>(i));
          per_segment[i] = MeasureSegment(scene,
                                          s,
                                          IsSupported(scene, s),
                                          index,
                                          fit,
                                          options.samples_per_segment,
                                          list_components);
        }
      },
      tbb::simple_partitioner{});
  ctx.ThrowIfCancelled(kSurfaceQualityStage);
}

/// The figures of the surface from its segments' figures, summed in segment order, with the
/// components in the order of FaceComponents (first face), each marked floating or not.
SurfaceQuality Aggregate(const PolygonMesh& mesh,
                         const Scene& scene,
                         const MeshIndex& index,
                         const std::vector<SegmentFigures>& per_segment,
                         double epsilon,
                         const SurfaceQualityOptions& options) {
  SurfaceQuality q;
  q.epsilon = epsilon;
  q.fit_distance = options.fit_factor * epsilon;
  q.components.resize(index.num_components);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    ComponentQuality& c = q.components[index.face_component[f]];
    ++c.faces;
    c.volume += FaceVolume(mesh, f);
  }
  double near = 0.0, sight = 0.0, clear = 0.0, sight_all = 0.0, clear_all = 0.0;
  std::vector<double> share(index.num_components, 0.0);
  const std::vector<std::uint32_t> line_of = LineOfSegment(scene);
  std::vector<std::vector<std::uint32_t>> lines_held(index.num_components);
  for (std::size_t i = 0; i < scene.NumSegments(); ++i) {
    const SegmentId s(i);
    const SegmentFigures& f = per_segment[i];
    sight_all += f.sight_length;
    clear_all += f.clear_length;
    if (!IsSupported(scene, s)) continue;
    ++q.supported_segments;
    q.supported_length += scene.segments[s].Length();
    near += f.near_length;
    sight += f.sight_length;
    clear += f.clear_length;
    if (f.near_by_component.empty()) continue;
    for (const auto& [c, length] : f.near_by_component) {
      q.components[c].supported_length += length;
      share[c] += length;
    }
    std::uint32_t best = f.near_by_component.front().first;
    for (const auto& [c, length] : f.near_by_component) {
      if (share[c] > share[best] || (share[c] == share[best] && c < best)) best = c;
    }
    ++q.components[best].supported_segments;
    lines_held[best].push_back(line_of[i]);
    for (const auto& [c, length] : f.near_by_component) share[c] = 0.0;
  }
  q.data_fit = q.supported_length > 0.0 ? near / q.supported_length : 0.0;
  q.visibility_consistency = sight > 0.0 ? clear / sight : 1.0;
  q.visibility_consistency_all = sight_all > 0.0 ? clear_all / sight_all : 1.0;

  for (std::size_t c = 0; c < index.num_components; ++c) {
    std::vector<std::uint32_t>& held = lines_held[c];
    std::sort(held.begin(), held.end());
    ComponentQuality& component = q.components[c];
    component.supported_lines =
        static_cast<std::size_t>(std::unique(held.begin(), held.end()) - held.begin());
    component.floating =
        component.supported_lines < static_cast<std::size_t>(options.min_lines_per_component);
  }
  return q;
}

/// A surface measured: its index, every segment's figures and the surface's (Aggregate).
struct Analysis {
  MeshIndex index;
  std::vector<SegmentFigures> per_segment;
  SurfaceQuality quality;
};

/// `list_components`: each segment's figures list the components they depend on.
Analysis Analyse(const PolygonMesh& mesh,
                 const Scene& scene,
                 double epsilon,
                 const SurfaceQualityOptions& options,
                 bool list_components,
                 const RunContext& ctx) {
  ThrowIfMembershipsMismatch(scene);
  Analysis out{IndexMesh(mesh), std::vector<SegmentFigures>(scene.NumSegments()), {}};
  MeasureSegments(
      scene,
      out.index,
      options,
      options.fit_factor * epsilon,
      list_components,
      ctx,
      [](std::size_t) { return true; },
      out.per_segment);
  out.quality = Aggregate(mesh, scene, out.index, out.per_segment, epsilon, options);
  return out;
}

/// The figures as reported: components by decreasing |volume|, the counts over them, the planes
/// on no face.
SurfaceQuality Summarise(SurfaceQuality q,
                         const PolygonMesh& mesh,
                         const Scene& scene,
                         double epsilon) {
  std::stable_sort(q.components.begin(),
                   q.components.end(),
                   [](const ComponentQuality& a, const ComponentQuality& b) {
                     return std::abs(a.volume) > std::abs(b.volume);
                   });
  for (const ComponentQuality& c : q.components) {
    q.floating_fragments += c.floating ? 1 : 0;
    q.enclosed_volume += std::abs(c.volume);
  }
  q.largest_component_share =
      q.enclosed_volume > 0.0 ? std::abs(q.components.front().volume) / q.enclosed_volume : 0.0;
  q.planes_off_surface = PlanesOffSurface(mesh, scene, epsilon);
  return q;
}

SurfaceQuality Measure(const PolygonMesh& mesh,
                       const Scene& scene,
                       double epsilon,
                       const SurfaceQualityOptions& options,
                       const RunContext& ctx) {
  return Summarise(
      Analyse(mesh, scene, epsilon, options, false, ctx).quality, mesh, scene, epsilon);
}

/// The figures of `kept`, the surface `index` measured into `per_segment` without the faces of
/// the components `removed` marks. A segment none of whose near samples' nearest faces and sight
/// rays' faces lies in a removed component keeps its figures (its nearest face and the faces
/// its rays meet are all kept); the others are measured again on `kept`.
SurfaceQuality MeasureWithout(const PolygonMesh& kept,
                              const Scene& scene,
                              const MeshIndex& index,
                              const std::vector<bool>& removed,
                              std::vector<SegmentFigures> per_segment,
                              double epsilon,
                              const SurfaceQualityOptions& options,
                              const RunContext& ctx) {
  const MeshIndex kept_index = IndexMesh(kept);
  // Components keep their faces: the old id of a kept face's component gives its new one.
  std::vector<ComponentId> new_component(index.num_components);  // invalid: removed
  for (std::size_t f = 0, k = 0; f < index.face_component.size(); ++f) {
    const std::uint32_t c = index.face_component[f];
    if (!removed[c]) new_component[c] = ComponentId(kept_index.face_component[k++]);
  }
  const auto touches_removed = [&](std::size_t i) {
    return std::any_of(per_segment[i].components.begin(),
                       per_segment[i].components.end(),
                       [&](std::uint32_t c) { return removed[c]; });
  };
  std::vector<char> again(per_segment.size());
  for (std::size_t i = 0; i < per_segment.size(); ++i) {
    again[i] = touches_removed(i) ? 1 : 0;
    if (again[i] != 0) continue;
    for (auto& [c, length] : per_segment[i].near_by_component) c = new_component[c].value();
  }
  MeasureSegments(
      scene,
      kept_index,
      options,
      options.fit_factor * epsilon,
      false,
      ctx,
      [&](std::size_t i) { return again[i] != 0; },
      per_segment);
  return Summarise(
      Aggregate(kept, scene, kept_index, per_segment, epsilon, options), kept, scene, epsilon);
}

FragmentRemoval RemoveFragments(const PolygonMesh& mesh,
                                const Scene& scene,
                                double epsilon,
                                const SurfaceQualityOptions& options,
                                const RunContext& ctx) {
  Analysis analysis = Analyse(mesh, scene, epsilon, options, true, ctx);
  const std::vector<ComponentQuality>& components = analysis.quality.components;
  const std::vector<std::uint32_t>& face_component = analysis.index.face_component;
  // Solid pieces only (positive volume: full cells inside): dropping the inner shell of a void
  // would fill the void. A surface of fragments only is left whole: what holds the most is not
  // known to be noise.
  const bool all_floating = std::all_of(
      components.begin(), components.end(), [](const ComponentQuality& c) { return c.floating; });
  std::vector<bool> removed(components.size());
  FragmentRemoval out;
  for (std::uint32_t c = 0; c < components.size(); ++c) {
    removed[c] = !all_floating && components[c].floating && components[c].volume > 0.0;
    if (!removed[c]) continue;
    ++out.removed_components;
    out.removed_volume += components[c].volume;
    out.removed_supported_segments += components[c].supported_segments;
  }
  if (out.removed_components == 0) {
    out.mesh = mesh;
    out.quality = Summarise(std::move(analysis.quality), mesh, scene, epsilon);
    return out;
  }
  // The kept faces and the vertices they use, each in their order.
  std::vector<std::uint8_t> used(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    if (removed[face_component[f]]) continue;
    for (std::uint32_t v : mesh.Face(f)) used[v] = 1;
  }
  std::vector<MeshVertexId> new_index(mesh.vertices.size());  // invalid: no kept face uses it
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (used[v] == 0) continue;
    new_index[v] = MeshVertexId(out.mesh.vertices.size());
    out.mesh.vertices.push_back(mesh.vertices[v]);
  }
  std::vector<std::uint32_t> face;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    if (removed[face_component[f]]) continue;
    face.clear();
    for (std::uint32_t v : mesh.Face(f)) face.push_back(new_index[v].value());
    out.mesh.AddFace(face);
  }
  out.quality = MeasureWithout(out.mesh,
                               scene,
                               analysis.index,
                               removed,
                               std::move(analysis.per_segment),
                               epsilon,
                               options,
                               ctx);
  return out;
}

}  // namespace

namespace {

Status ValidateArguments(const SurfaceQualityOptions& options, double epsilon) {
  if (Status s = ValidateOptionValues(options); !s) return s;
  if (!(epsilon > 0.0 && std::isfinite(epsilon))) {
    return Error{ErrorCode::kInvalidOptions, kSurfaceQualityStage, "epsilon must be > 0"};
  }
  return {};
}

}  // namespace

Expected<SurfaceQuality> MeasureSurfaceQuality(const PolygonMesh& mesh,
                                               const Scene& scene,
                                               double epsilon,
                                               const SurfaceQualityOptions& options,
                                               const RunContext& ctx) noexcept {
  if (Status s = ValidateArguments(options, epsilon); !s) return s.error();
  return CatchAll(kSurfaceQualityStage, [&] {
    return RunInArena(ctx, [&] { return Measure(mesh, scene, epsilon, options, ctx); });
  });
}

Expected<FragmentRemoval> RemoveFloatingFragments(const PolygonMesh& mesh,
                                                  const Scene& scene,
                                                  double epsilon,
                                                  const SurfaceQualityOptions& options,
                                                  const RunContext& ctx) noexcept {
  if (Status s = ValidateArguments(options, epsilon); !s) return s.error();
  return CatchAll(kSurfaceQualityStage, [&] {
    return RunInArena(ctx, [&] { return RemoveFragments(mesh, scene, epsilon, options, ctx); });
  });
}

}  // namespace linesurf::pipeline
