#include "engine/pipeline/open_seams.h"

#include "engine/pipeline/extract_block_surface.h"
#include "engine/pipeline/segment_evidence.h"

#include <cstdint>

#include <vector>

namespace linesurf::pipeline {
namespace {

double FaceArea(const PolygonMesh& mesh, std::size_t f, std::vector<Vec3>& points) {
  points.clear();
  for (const std::uint32_t v : mesh.Face(f)) points.push_back(mesh.vertices[v]);
  return PolygonArea(points);
}

}  // namespace

bool SeamCarriesPlane(const partition::BlockComplexes& complexes, std::size_t seam) {
  const partition::SeamFace& face = complexes.seams[seam];
  // The face is the lower block's max face (box plane 3 + axis), the upper block's min face.
  const auto axis = static_cast<std::size_t>(face.axis);
  return complexes.blocks[face.lower_block].face_planes[3 + axis].IsValid() ||
         complexes.blocks[face.upper_block].face_planes[axis].IsValid();
}

OpenSeamSurface MeasureOpenSeamSurface(const partition::BlockComplexes& complexes,
                                       const PolygonMesh& mesh,
                                       std::span<const BlockFacetRef> face_facet) {
  std::vector<char> open(complexes.seams.size());
  for (std::size_t s = 0; s < open.size(); ++s) open[s] = SeamCarriesPlane(complexes, s) ? 0 : 1;
  OpenSeamSurface out;
  std::vector<Vec3> points;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const double area = FaceArea(mesh, f, points);
    out.total_area += area;
    if (face_facet[f].seam && open[face_facet[f].owner] != 0) {
      ++out.faces;
      out.area += area;
    }
  }
  return out;
}

}  // namespace linesurf::pipeline
