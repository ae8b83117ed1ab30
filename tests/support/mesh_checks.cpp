#include "tests/support/mesh_checks.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "engine/core/disjoint_sets.h"

namespace linesurf::testing {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

struct Component {
  Mesh mesh;  // triangulated
  bool manifold = false;
  bool closed = false;
  double volume = 0.0;
  CGAL::Bbox_3 box;
  std::vector<Point> points;
};

MeshCheckReport Run(const PolygonMesh& mesh) {
  MeshCheckReport report;
  const std::size_t nv = mesh.vertices.size();
  DisjointSets sets(nv);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    if (face.size() < 3) return report;
    for (std::uint32_t v : face) {
      if (v >= nv) return report;
      sets.Union(v, face[0]);
    }
  }
  // Components in order of their smallest face; vertices renumbered per component.
  std::vector<std::size_t> component_of_root(nv, SIZE_MAX);
  std::vector<std::vector<Point>> points;
  std::vector<std::vector<std::vector<std::size_t>>> polygons;
  std::vector<std::size_t> local(nv, SIZE_MAX);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    const std::size_t root = sets.Find(face[0]);
    if (component_of_root[root] == SIZE_MAX) {
      component_of_root[root] = points.size();
      points.emplace_back();
      polygons.emplace_back();
    }
    const std::size_t c = component_of_root[root];
    std::vector<std::size_t> polygon;
    for (std::uint32_t v : face) {
      if (local[v] == SIZE_MAX) {
        local[v] = points[c].size();
        const Vec3& p = mesh.vertices[v];
        points[c].emplace_back(p.x(), p.y(), p.z());
      }
      polygon.push_back(local[v]);
    }
    polygons[c].push_back(std::move(polygon));
  }
  report.num_components = points.size();
  std::vector<Component> components(points.size());
  report.two_manifold = true;
  report.closed = true;
  for (std::size_t c = 0; c < points.size(); ++c) {
    Component& comp = components[c];
    comp.manifold = PMP::is_polygon_soup_a_polygon_mesh(polygons[c]);
    if (!comp.manifold) {
      report.two_manifold = false;
      report.closed = false;
      continue;
    }
    PMP::polygon_soup_to_polygon_mesh(points[c], polygons[c], comp.mesh);
    comp.closed = CGAL::is_closed(comp.mesh);
    if (!comp.closed) {
      report.closed = false;
      continue;
    }
    if (!PMP::triangulate_faces(comp.mesh)) {
      report.closed = false;
      continue;
    }
    comp.volume = PMP::volume(comp.mesh);
    comp.points = points[c];
    comp.box = CGAL::bbox_3(points[c].begin(), points[c].end());
  }
  if (!report.closed) return report;
  report.outward_oriented = true;
  for (std::size_t c = 0; c < components.size(); ++c) {
    report.volume += components[c].volume;
    // Nesting depth: how many other components enclose this one (tested at the first of its
    // vertices that is strictly inside or outside).
    int depth = 0;
    for (std::size_t d = 0; d < components.size(); ++d) {
      if (d == c) continue;
      const CGAL::Bbox_3& inner = components[c].box;
      const CGAL::Bbox_3& outer = components[d].box;
      if (inner.xmin() < outer.xmin() || inner.ymin() < outer.ymin() ||
          inner.zmin() < outer.zmin() || inner.xmax() > outer.xmax() ||
          inner.ymax() > outer.ymax() || inner.zmax() > outer.zmax()) {
        continue;
      }
      CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(components[d].mesh);
      for (const Point& p : components[c].points) {
        const CGAL::Bounded_side s = side(p);
        if (s == CGAL::ON_BOUNDARY) continue;
        if (s == CGAL::ON_BOUNDED_SIDE) ++depth;
        break;
      }
    }
    const bool expect_positive = depth % 2 == 0;
    if ((components[c].volume > 0.0) != expect_positive || components[c].volume == 0.0) {
      report.outward_oriented = false;
    }
  }
  return report;
}

}  // namespace

MeshCheckReport CheckMesh(const PolygonMesh& mesh) {
  try {
    return Run(mesh);
  } catch (...) {
    return MeshCheckReport{};
  }
}

bool IsTwoManifold(const PolygonMesh& mesh) { return CheckMesh(mesh).two_manifold; }
bool IsClosed(const PolygonMesh& mesh) { return CheckMesh(mesh).closed; }
bool IsOutwardOriented(const PolygonMesh& mesh) { return CheckMesh(mesh).outward_oriented; }
double Volume(const PolygonMesh& mesh) { return CheckMesh(mesh).volume; }

std::vector<bool> PointsStrictlyInside(const PolygonMesh& mesh, const std::vector<Vec3>& points) {
  try {
    std::vector<Point> soup_points;
    for (const Vec3& v : mesh.vertices) soup_points.emplace_back(v.x(), v.y(), v.z());
    std::vector<std::vector<std::size_t>> polygons;
    for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
      const auto face = mesh.Face(f);
      polygons.emplace_back(face.begin(), face.end());
    }
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return {};
    Mesh sm;
    PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, sm);
    if (!PMP::triangulate_faces(sm)) return {};
    CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(sm);
    std::vector<bool> inside;
    inside.reserve(points.size());
    for (const Vec3& p : points) {
      inside.push_back(side(Point(p.x(), p.y(), p.z())) == CGAL::ON_BOUNDED_SIDE);
    }
    return inside;
  } catch (...) {
    return {};
  }
}

}  // namespace linesurf::testing
