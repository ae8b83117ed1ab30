#include "engine/pipeline/surface_quality.h"

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
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

namespace linesurf::pipeline {
namespace {

constexpr const char* kSurfaceQualityStage = "surface_quality";
/// Segments per parallel task; fixed so the chunking never depends on the thread count.
constexpr std::size_t kSegmentGrain = 64;
constexpr int kMaxSamplesPerSegment = 1024;
/// A vertex no kept face uses.
constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
/// Parts of one line: every endpoint within this fraction of the median segment length of the
/// other's line (as eps auto counts them).
constexpr double kCollinearPartsOverMedianLength = 1e-5;

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
  std::vector<std::uint32_t> id_of_root(nv, std::numeric_limits<std::uint32_t>::max());
  std::vector<std::uint32_t> out(mesh.NumFaces());
  count = 0;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const std::size_t root = sets.Find(mesh.Face(f)[0]);
    if (id_of_root[root] == std::numeric_limits<std::uint32_t>::max()) {
      id_of_root[root] = static_cast<std::uint32_t>(count++);
    }
    out[f] = id_of_root[root];
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
                              int samples) {
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
    }
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

std::vector<std::uint32_t> PlanesOffSurface(const PolygonMesh& mesh,
                                            const Scene& scene,
                                            double eps) {
  std::vector<bool> on(scene.planes.size(), false);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    if (face.size() < 3) continue;
    for (std::size_t p = 0; p < on.size(); ++p) {
      if (on[p]) continue;
      const Plane3& plane = scene.planes.raw()[p];
      on[p] = std::all_of(face.begin(), face.end(), [&](std::uint32_t v) {
        return std::abs(plane.SignedDistance(mesh.vertices[v])) <= eps;
      });
    }
  }
  std::vector<std::uint32_t> off;
  for (std::size_t p = 0; p < on.size(); ++p) {
    if (!on[p]) off.push_back(static_cast<std::uint32_t>(p));
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

/// The figures with the components in the order of FaceComponents (first face), each marked
/// floating or not, and the component of every face.
struct ComponentFigures {
  SurfaceQuality quality;
  std::vector<std::uint32_t> face_component;
};

ComponentFigures Analyse(const PolygonMesh& mesh,
                         const Scene& scene,
                         double epsilon,
                         const SurfaceQualityOptions& options,
                         const RunContext& ctx) {
  LINESURF_THROW_IF(
      scene.HasMemberships() && scene.memberships.size() != scene.NumSegments(),
      kInvalidInput,
      kSurfaceQualityStage,
      "memberships: " << scene.memberships.size() << " for " << scene.NumSegments() << " segments");
  const MeshIndex index = IndexMesh(mesh);
  const double fit = options.fit_factor * epsilon;
  const auto supported = [&](SegmentId s) {
    return scene.HasMemberships() && scene.memberships[s].count > 0;
  };

  std::vector<SegmentFigures> per_segment(scene.NumSegments());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, scene.NumSegments(), kSegmentGrain),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (ctx.ShouldStop()) return;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const SegmentId s(static_cast<std::uint32_t>(i));
          per_segment[i] =
              MeasureSegment(scene, s, supported(s), index, fit, options.samples_per_segment);
        }
      },
      tbb::simple_partitioner{});
  ctx.ThrowIfCancelled(kSurfaceQualityStage);

  SurfaceQuality q;
  q.epsilon = epsilon;
  q.fit_distance = fit;
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
    if (!supported(s)) continue;
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
  return {std::move(q), index.face_component};
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
  return Summarise(Analyse(mesh, scene, epsilon, options, ctx).quality, mesh, scene, epsilon);
}

FragmentRemoval RemoveFragments(const PolygonMesh& mesh,
                                const Scene& scene,
                                double epsilon,
                                const SurfaceQualityOptions& options,
                                const RunContext& ctx) {
  const ComponentFigures figures = Analyse(mesh, scene, epsilon, options, ctx);
  const std::vector<ComponentQuality>& components = figures.quality.components;
  // Solid pieces only (positive volume: full cells inside): dropping the inner shell of a void
  // would fill the void.
  const auto removed = [&](std::uint32_t c) {
    return components[c].floating && components[c].volume > 0.0;
  };
  FragmentRemoval out;
  out.quality = Summarise(figures.quality, mesh, scene, epsilon);
  // A surface of fragments only is left whole: what holds the most is not known to be noise.
  if (std::all_of(components.begin(), components.end(), [](const ComponentQuality& c) {
        return c.floating;
      })) {
    out.mesh = mesh;
    return out;
  }
  for (std::uint32_t c = 0; c < components.size(); ++c) {
    if (!removed(c)) continue;
    ++out.removed_components;
    out.removed_volume += components[c].volume;
    out.removed_supported_segments += components[c].supported_segments;
  }
  // The kept faces and the vertices they use, each in their order: the mesh is unchanged when
  // nothing is removed.
  std::vector<std::uint32_t> new_index(mesh.vertices.size(), kNoVertex);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    if (removed(figures.face_component[f])) continue;
    for (std::uint32_t v : mesh.Face(f)) new_index[v] = 0;
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (new_index[v] == kNoVertex) continue;
    new_index[v] = static_cast<std::uint32_t>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(mesh.vertices[v]);
  }
  std::vector<std::uint32_t> face;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    if (removed(figures.face_component[f])) continue;
    face.clear();
    for (std::uint32_t v : mesh.Face(f)) face.push_back(new_index[v]);
    out.mesh.AddFace(face);
  }
  return out;
}

}  // namespace

Status SurfaceQualityOptions::Validate() const {
  if (!(fit_factor > 0.0 && std::isfinite(fit_factor))) {
    return Error{ErrorCode::kInvalidOptions, kSurfaceQualityStage, "fit_factor must be > 0"};
  }
  if (min_lines_per_component < 0) {
    return Error{
        ErrorCode::kInvalidOptions, kSurfaceQualityStage, "min_lines_per_component must be >= 0"};
  }
  if (samples_per_segment < 1 || samples_per_segment > kMaxSamplesPerSegment) {
    return Error{ErrorCode::kInvalidOptions,
                 kSurfaceQualityStage,
                 "samples_per_segment must be in [1, 1024]"};
  }
  return {};
}

namespace {

Status ValidateArguments(const SurfaceQualityOptions& options, double epsilon) {
  if (Status s = options.Validate(); !s) return s;
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
