#include "tests/support/one_complex_surface.h"

#include "engine/core/exception.h"
#include "engine/pipeline/surface_assembly.h"

#include <vector>

namespace linesurf::pipeline::testing {
namespace {

constexpr const char* kExtractSurfaceStage = "extract_surface";

/// The facets between cells of different labels as cycles oriented from full to empty, in
/// FacetId order; `face_of_facet` receives the face of every facet (invalid off the surface).
SurfaceCycles CollectSurfaceFaces(const CellComplex& cx,
                                  std::span<const std::uint8_t> labels,
                                  bool outside_full,
                                  std::vector<FacetId>& face_facet,
                                  std::vector<SurfaceFaceId>& face_of_facet) {
  const auto full_cell = [&](CellId c) {
    return c.IsValid() ? labels[c.index()] != 0 : outside_full;
  };
  SurfaceCycles s;
  face_of_facet.assign(cx.NumFacets(), SurfaceFaceId::Invalid());
  std::vector<std::uint32_t> vertices;
  std::vector<std::uint32_t> edges;
  for (std::size_t fi = 0; fi < cx.NumFacets(); ++fi) {
    const FacetId f(fi);
    const bool pos_full = full_cell(cx.facet_positive_cell[f]);
    if (pos_full == full_cell(cx.facet_negative_cell[f])) continue;
    vertices.clear();
    edges.clear();
    for (const VertexId v : cx.facet_vertices[f]) vertices.push_back(v.value());
    for (const EdgeId e : cx.facet_edges[f]) edges.push_back(e.value());
    face_of_facet[fi] = SurfaceFaceId(face_facet.size());
    face_facet.push_back(f);
    // The stored cycle is counter-clockwise seen from the positive side, so its normal points to
    // the positive cell: keep it when that cell is the empty one, reverse it otherwise.
    s.AddCycle(vertices, edges, pos_full);
  }
  return s;
}

}  // namespace

Expected<ExtractResult> ExtractOneComplexSurface(const CellComplex& cx,
                                                 std::span<const std::uint8_t> labels,
                                                 const ExtractOptions& options) noexcept {
  return CatchAll(kExtractSurfaceStage, [&]() -> ExtractResult {
    LINESURF_THROW_IF(
        labels.size() != cx.NumCells(),
        kInvalidInput,
        kExtractSurfaceStage,
        "labels has " << labels.size() << " entries for " << cx.NumCells() << " cells");
    std::vector<FacetId> facet_of_face;
    std::vector<SurfaceFaceId> face_of_facet;
    SurfaceCycles s =
        CollectSurfaceFaces(cx, labels, options.outside_full, facet_of_face, face_of_facet);
    ExtractResult result;
    result.stats.surface_facets = s.NumFaces();
    std::vector<EdgePair> crowded;
    result.stats.non_manifold_edges =
        PairAroundComplexEdges(cx, labels, options.outside_full, face_of_facet, 0, {}, s, crowded);
    AssembledSurface surface =
        AssembleSurface(s, cx.vertex_points.raw(), crowded, options.triangulate);
    result.mesh = std::move(surface.mesh);
    result.stats.split_vertices = surface.split_vertices;
    result.face_facet.reserve(surface.face_cycle.size());
    for (const std::uint32_t f : surface.face_cycle) result.face_facet.push_back(facet_of_face[f]);
    result.vertex_source.reserve(surface.vertex_source.size());
    for (const CandidateVertexId v : surface.vertex_source) {
      result.vertex_source.push_back(v.IsValid() ? VertexId(v.value()) : VertexId::Invalid());
    }
    return result;
  });
}

}  // namespace linesurf::pipeline::testing
