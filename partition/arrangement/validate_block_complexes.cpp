#include "engine/core/exception.h"
#include "partition/arrangement/block_complexes.h"
#include "partition/arrangement/cell_geometry.h"
#include "partition/arrangement/seam_overlay.h"
#include "partition/arrangement/validate_cell_complex.h"

#include <cmath>

namespace linesurf::partition {
namespace {

constexpr char kValidateBlockComplexesStage[] = "validate_block_complexes";

#define LINESURF_CHECK(cond, msg) \
  LINESURF_THROW_IF(!(cond), kInternal, kValidateBlockComplexesStage, msg)

bool Near(double value, double expected, double tolerance) {
  return std::abs(value - expected) <= tolerance * std::abs(expected);
}

void CheckBlock(const BlockComplexes& cx, std::size_t b, double tolerance) {
  const BlockComplex& block = cx.blocks[b];
  const CellComplex& c = block.complex;
  if (Status ok = ValidateCellComplex(c); !ok) {
    throw LinesurfException(Error{ErrorCode::kInternal,
                                  kValidateBlockComplexesStage,
                                  "block " + std::to_string(b) + ": " + ok.error().message});
  }
  const Box3 box = cx.grid.BlockBox({0, block.base});
  LINESURF_CHECK(c.box.min == box.min && c.box.max == box.max,
                 "block " << b << ": the complex's box is not the grid's block box");
  double volume = 0.0;
  for (std::size_t k = 0; k < c.NumCells(); ++k) volume += CellVolume(c, CellId(k));
  LINESURF_CHECK(Near(volume, box.Extent().prod(), tolerance),
                 "block " << b << ": cell volumes sum to " << volume << ", the block holds "
                          << box.Extent().prod());
  LINESURF_CHECK(
      block.plane_keys.size() == c.planes.size() && block.facet_kind.size() == c.NumFacets(),
      "block " << b << ": key or kind arrays differ in size");
  for (std::size_t k = 0; k < c.planes.size(); ++k) {
    const PlaneKey key = block.plane_keys[k];
    LINESURF_CHECK(key.IsFace() == (k < kNumBoxPlanes), "block " << b << ": plane " << k << " key");
    if (k >= kNumBoxPlanes) {
      LINESURF_CHECK(key.plane() == c.planes[ComplexPlaneId(k)].source,
                     "block " << b << ": plane " << k << " key and source differ");
    }
  }
  for (std::size_t f = 0; f < c.NumFacets(); ++f) {
    const std::size_t k = c.facet_plane[FacetId(f)].index();
    const FacetKind kind = block.facet_kind[FacetId(f)];
    if (k >= kNumBoxPlanes) {
      LINESURF_CHECK(kind == FacetKind::kInterior, "block " << b << ": facet " << f << " kind");
      continue;
    }
    const int axis = static_cast<int>(k % 3);
    const bool on_box =
        k < 3 ? block.base[axis] == 0 : block.base[axis] == cx.grid.dims()[axis] - 1;
    LINESURF_CHECK(kind == (on_box ? FacetKind::kSceneBoundary : FacetKind::kSeam),
                   "block " << b << ": facet " << f << " kind");
  }
}

double SumOfAreas(const BlockComplex& block, int local_face) {
  const CellComplex& c = block.complex;
  double area = 0.0;
  for (std::size_t f = 0; f < c.NumFacets(); ++f) {
    if (c.facet_plane[FacetId(f)].index() != static_cast<std::size_t>(local_face)) continue;
    std::vector<Vec3> points;
    for (const VertexId v : c.facet_vertices[FacetId(f)]) points.push_back(c.vertex_points[v]);
    area += PolygonArea(points);
  }
  return area;
}

bool InsidePolygon(const BlockComplexes& cx, const VertexKey& v, const SeamPolygon& p) {
  for (std::size_t e = 0; e < p.edge_planes.size(); ++e) {
    if (p.edge_sides[e] * SignAt(cx, v, p.edge_planes[e]) < 0) return false;
  }
  return true;
}

void CheckSeam(const BlockComplexes& cx, std::size_t s, double tolerance) {
  const SeamFace& face = cx.seams[s];
  LINESURF_CHECK(face.lower_block < cx.blocks.size() && face.upper_block < cx.blocks.size(),
                 "seam " << s << ": block out of range");
  const BlockComplex& lower = cx.blocks[face.lower_block];
  const BlockComplex& upper = cx.blocks[face.upper_block];
  Eigen::Vector3i up = lower.base;
  ++up[face.axis];
  LINESURF_CHECK(up == upper.base, "seam " << s << ": the blocks are not neighbours");
  const Box3 box = cx.grid.BlockBox({0, lower.base});
  Vec3 extent = box.Extent();
  extent[face.axis] = 1.0;
  const double face_area = extent.prod();
  const double lower_area = SumOfAreas(lower, 3 + face.axis);
  const double upper_area = SumOfAreas(upper, face.axis);
  LINESURF_CHECK(Near(lower_area, face_area, tolerance) && Near(upper_area, face_area, tolerance),
                 "seam " << s << ": the blocks' facets on the face cover " << lower_area << " and "
                         << upper_area << " of " << face_area);
  const PlaneKey key = BoxPlaneKey(lower.base, 3 + face.axis);
  LINESURF_CHECK(key == BoxPlaneKey(upper.base, face.axis),
                 "seam " << s << ": the blocks disagree on the face key");
  const std::vector<SeamPolygon> lower_polygons = FacePolygons(lower, 3 + face.axis);
  const std::vector<SeamPolygon> upper_polygons = FacePolygons(upper, face.axis);
  const auto find = [](const std::vector<SeamPolygon>& polygons, FacetId f) {
    return std::find_if(
        polygons.begin(), polygons.end(), [&](const SeamPolygon& p) { return p.facet == f; });
  };
  double area = 0.0;
  for (std::size_t i = 0; i < face.facets.size(); ++i) {
    const SeamFacet& facet = face.facets[i];
    const auto a = find(lower_polygons, facet.lower_facet);
    const auto b = find(upper_polygons, facet.upper_facet);
    LINESURF_CHECK(a != lower_polygons.end() && b != upper_polygons.end(),
                   "seam " << s << " facet " << i << ": a parent is not a facet on the face");
    LINESURF_CHECK(facet.lower_cell == a->cell && facet.upper_cell == b->cell,
                   "seam " << s << " facet " << i << ": cells are not those of its parents");
    LINESURF_CHECK(facet.vertices.size() >= 3 && facet.points.size() == facet.vertices.size() &&
                       facet.edge_planes.size() == facet.vertices.size(),
                   "seam " << s << " facet " << i << ": fewer than 3 vertices");
    for (const VertexKey& v : facet.vertices) {
      LINESURF_CHECK(
          SignAt(cx, v, key) == 0 && InsidePolygon(cx, v, *a) && InsidePolygon(cx, v, *b),
          "seam " << s << " facet " << i << ": a vertex is off the face or outside "
                  << "a parent facet");
    }
    LINESURF_CHECK(HasArea(cx, facet.vertices, facet.edge_planes),
                   "seam " << s << " facet " << i << ": zero area");
    for (std::size_t k = 0; k < facet.vertices.size(); ++k) {
      const VertexKey& next = facet.vertices[(k + 1) % facet.vertices.size()];
      LINESURF_CHECK(SignAt(cx, facet.vertices[k], facet.edge_planes[k]) == 0 &&
                         SignAt(cx, next, facet.edge_planes[k]) == 0,
                     "seam " << s << " facet " << i << ": edge " << k << " is off its plane");
    }
    area += PolygonArea(facet.points);
  }
  LINESURF_CHECK(Near(area, face_area, tolerance),
                 "seam " << s << ": seam facets cover " << area << " of " << face_area);
}

}  // namespace

Status ValidateBlockComplexes(const BlockComplexes& cx, double relative_tolerance) noexcept {
  return CatchAll(kValidateBlockComplexesStage, [&] {
    LINESURF_CHECK(static_cast<std::int64_t>(cx.blocks.size()) == cx.grid.NumBaseBlocks(),
                   "not one complex per base block");
    for (std::size_t b = 0; b < cx.blocks.size(); ++b) {
      LINESURF_CHECK(cx.blocks[b].base == cx.grid.BaseFromLinear(static_cast<std::int64_t>(b)),
                     "block " << b << " is out of order");
      CheckBlock(cx, b, relative_tolerance);
    }
    std::size_t expected = 0;
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3i d = cx.grid.dims();
      --d[a];
      expected += static_cast<std::size_t>(d.x()) * d.y() * d.z();
    }
    LINESURF_CHECK(cx.seams.size() == expected,
                   "seams: " << cx.seams.size() << " faces, the grid has " << expected);
    for (std::size_t s = 0; s < cx.seams.size(); ++s) CheckSeam(cx, s, relative_tolerance);
  });
}

}  // namespace linesurf::partition
