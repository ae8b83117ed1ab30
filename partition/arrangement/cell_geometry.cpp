#include "partition/arrangement/cell_geometry.h"

#include <algorithm>

#include <Eigen/Geometry>

namespace linesurf::partition {

std::vector<VertexId> OutwardFacetCycle(const CellComplex& complex, FacetId f, CellId c) {
  const auto cycle = complex.facet_vertices[f];
  std::vector<VertexId> out(cycle.begin(), cycle.end());
  // Stored cycles are counter-clockwise seen from the positive side, which is outside the
  // negative cell.
  if (complex.facet_positive_cell[f] == c) std::reverse(out.begin(), out.end());
  return out;
}

std::vector<VertexId> CellVertices(const CellComplex& complex, CellId c) {
  std::vector<VertexId> vertices;
  for (const FacetId f : complex.cell_facets[c]) {
    for (const VertexId v : complex.facet_vertices[f]) vertices.push_back(v);
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

Vec3 CellCentroid(const CellComplex& complex, CellId c) {
  const auto vertices = CellVertices(complex, c);
  Vec3 sum = Vec3::Zero();
  for (const VertexId v : vertices) sum += complex.vertex_points[v];
  return vertices.empty() ? sum : Vec3(sum / static_cast<double>(vertices.size()));
}

double CellVolume(const CellComplex& complex, CellId c) {
  const Vec3 r = CellCentroid(complex, c);
  double six_volume = 0.0;
  for (const FacetId f : complex.cell_facets[c]) {
    const auto cycle = OutwardFacetCycle(complex, f, c);
    const Vec3 a = complex.vertex_points[cycle[0]] - r;
    for (std::size_t i = 1; i + 1 < cycle.size(); ++i) {
      const Vec3 b = complex.vertex_points[cycle[i]] - r;
      const Vec3 d = complex.vertex_points[cycle[i + 1]] - r;
      six_volume += a.dot(b.cross(d));
    }
  }
  return six_volume / 6.0;
}

}  // namespace linesurf::partition
