#include "engine/pipeline/mesh_validity.h"

#include "engine/core/coordinate_bound.h"
#include "engine/core/exception.h"
#include "engine/core/vector_area.h"
#include "engine/pipeline/mesh_topology.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace linesurf {
namespace {

constexpr const char* kCheckMeshStage = "check_mesh";
/// Flatness and planarity tolerances, relative to the bounding-box diagonal: far above the
/// rounding of computed vertices (1e-16), far below any real feature.
constexpr double kFlatRelative = 1e-9;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;

/// Number of vertices at the bit-identical position of a vertex with a smaller index.
std::size_t CountCoincidentVertices(const PolygonMesh& mesh) {
  std::vector<std::uint32_t> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0U);
  const auto key = [&](std::uint32_t v) {
    const Vec3& p = mesh.vertices[v];
    return std::make_tuple(p.x(), p.y(), p.z(), v);
  };
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::size_t coincident = 0;
  for (std::size_t i = 1; i < order.size(); ++i) {
    coincident += mesh.vertices[order[i]] == mesh.vertices[order[i - 1]] ? 1 : 0;
  }
  return coincident;
}

struct TrianglePairs {
  std::size_t intersecting = 0;
  std::size_t touching = 0;
};

TrianglePairs IntersectingPairs(const PolygonMesh& mesh,
                                const std::vector<std::vector<std::size_t>>& faces) {
  if (faces.empty()) return {};
  std::vector<Kernel::Point_3> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polygons = faces;
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    // Splits non-manifold vertices and flips faces so that a halfedge mesh can hold the soup.
    PMP::orient_polygon_soup(points, polygons);
  }
  CgalMesh cgal_mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, cgal_mesh);
  LINESURF_THROW_IF(!PMP::triangulate_faces(cgal_mesh),
                    kDegenerate,
                    kCheckMeshStage,
                    "a face could not be triangulated for the self-intersection test");
  using Face = CgalMesh::Face_index;
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(CGAL::faces(cgal_mesh), cgal_mesh, std::back_inserter(pairs));
  // Faces that meet at a common position without sharing the vertex (split non-manifold
  // vertices, coincident copies) touch there; they are counted apart.
  const auto corners = [&](Face f) {
    std::vector<Kernel::Point_3> out;
    for (auto v : CGAL::vertices_around_face(cgal_mesh.halfedge(f), cgal_mesh)) {
      out.push_back(cgal_mesh.point(v));
    }
    return out;
  };
  TrianglePairs counts;
  for (const auto& [f, g] : pairs) {
    bool touching = false;
    for (const auto& p : corners(f)) {
      for (const auto& q : corners(g)) touching = touching || p == q;
    }
    ++(touching ? counts.touching : counts.intersecting);
  }
  return counts;
}

/// Whether `face` is thinner than `tolerance` (twice its area over its longest edge), and
/// whether a vertex is farther than `tolerance` from its plane.
std::pair<bool, bool> FlatAndPlanar(const PolygonMesh& mesh,
                                    const std::vector<std::size_t>& face,
                                    double tolerance) {
  const Vec3 twice_area = TwiceVectorArea(
      face.size(), [&](std::size_t k) -> const Vec3& { return mesh.vertices[face[k]]; });
  double longest = 0.0;
  Vec3 centroid = Vec3::Zero();
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Vec3& p = mesh.vertices[face[k]];
    longest = std::max(longest, (mesh.vertices[face[(k + 1) % face.size()]] - p).norm());
    centroid += p;
  }
  centroid /= static_cast<double>(face.size());
  const double norm = twice_area.norm();
  const bool flat = norm <= tolerance * longest;
  bool planar = true;
  if (!flat) {
    const Vec3 normal = twice_area / norm;
    for (const std::size_t v : face) {
      planar = planar && std::abs(normal.dot(mesh.vertices[v] - centroid)) <= tolerance;
    }
  }
  return {flat, planar};
}

/// Every face offset and index is in range.
void CheckIndices(const PolygonMesh& mesh) {
  const std::size_t num_vertices = mesh.vertices.size();
  LINESURF_THROW_IF(mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 ||
                        mesh.face_offsets.back() != mesh.face_indices.size(),
                    kInvalidInput,
                    kCheckMeshStage,
                    "face offsets do not cover the face indices");
  for (std::size_t i = 0; i < mesh.face_indices.size(); ++i) {
    LINESURF_THROW_IF(mesh.face_indices[i] >= num_vertices,
                      kInvalidInput,
                      kCheckMeshStage,
                      "face index " << i << " refers to vertex " << mesh.face_indices[i] << " of "
                                    << num_vertices);
  }
}

/// Faces by vertex index (consecutive repeats folded); those with fewer than 3 distinct vertices
/// or a repeated vertex are degenerate, counted in `topo`, and take no part in the checks.
std::vector<std::vector<std::size_t>> NonDegenerateFaces(const PolygonMesh& mesh,
                                                         MeshValidity& topo) {
  std::vector<std::vector<std::size_t>> faces;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    std::vector<std::size_t> face;
    for (std::uint32_t v : mesh.Face(f)) {
      if (face.empty() || face.back() != v) face.push_back(v);
    }
    while (face.size() > 1 && face.front() == face.back()) face.pop_back();
    std::vector<std::size_t> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (face.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++topo.num_degenerate_faces;
      continue;
    }
    faces.push_back(std::move(face));
  }
  return faces;
}

/// Counts the zero-area and non-planar faces in `topo`; returns the faces with area (zero-area
/// faces cannot be triangulated for the self-intersection test: they sit it out).
std::vector<std::vector<std::size_t>> FacesWithArea(
    const PolygonMesh& mesh, const std::vector<std::vector<std::size_t>>& faces, MeshValidity& topo) {
  Box3 box;
  for (const Vec3& p : mesh.vertices) box.Extend(p);
  const double tolerance = box.IsEmpty() ? 0.0 : kFlatRelative * box.Extent().norm();
  std::vector<std::vector<std::size_t>> with_area;
  for (const auto& face : faces) {
    const auto [flat, planar] = FlatAndPlanar(mesh, face, tolerance);
    topo.num_zero_area_faces += flat ? 1 : 0;
    topo.num_non_planar_faces += planar ? 0 : 1;
    if (!flat) with_area.push_back(face);
  }
  return with_area;
}

/// Area over a fan triangulation: a planar face's area is the length of the sum of its fan's
/// vector areas, convex or not (merged faces are not).
double Area(const PolygonMesh& mesh, const std::vector<std::vector<std::size_t>>& faces) {
  double area = 0.0;
  for (const auto& face : faces) {
    area += 0.5 * TwiceVectorArea(face.size(), [&](std::size_t k) -> const Vec3& {
              return mesh.vertices[face[k]];
            }).norm();
  }
  return area;
}

/// The edge and fan topology of `faces` (mesh_topology.h).
pipeline::MeshTopology FaceTopology(const PolygonMesh& mesh,
                                    const std::vector<std::vector<std::size_t>>& faces) {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  for (const auto& face : faces) {
    for (const std::size_t v : face) indices.push_back(static_cast<std::uint32_t>(v));
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
  }
  return pipeline::ComputeMeshTopology(mesh.vertices, offsets, indices);
}

MeshValidity Check(const PolygonMesh& mesh) {
  CheckIndices(mesh);
  MeshValidity topo;
  topo.num_faces = mesh.NumFaces();
  topo.num_vertices = mesh.vertices.size();
  topo.num_coincident_vertices = CountCoincidentVertices(mesh);
  const std::vector<std::vector<std::size_t>> faces = NonDegenerateFaces(mesh, topo);
  const std::vector<std::vector<std::size_t>> with_area = FacesWithArea(mesh, faces, topo);
  const pipeline::MeshTopology edges = FaceTopology(mesh, faces);
  topo.signed_volume = edges.signed_volume;
  topo.area = Area(mesh, faces);
  topo.num_boundary_edges = edges.num_boundary_edges;
  topo.num_non_manifold_edges = edges.num_non_manifold_edges;
  topo.num_components = edges.num_components;
  topo.num_non_manifold_vertices = edges.num_non_manifold_vertices;

  topo.closed = !faces.empty() && topo.num_boundary_edges == 0 && topo.num_non_manifold_edges == 0;
  topo.two_manifold = topo.num_non_manifold_edges == 0 && topo.num_non_manifold_vertices == 0;
  topo.oriented = edges.consistent && topo.num_non_manifold_edges == 0;
  topo.outward = topo.closed && topo.oriented && topo.signed_volume > 0.0;
  const TrianglePairs pairs = IntersectingPairs(mesh, with_area);
  topo.num_intersecting_triangle_pairs = pairs.intersecting;
  topo.num_touching_triangle_pairs = pairs.touching;
  topo.self_intersecting = pairs.intersecting > 0;
  return topo;
}

}  // namespace

Expected<MeshValidity> CheckMeshValidity(const PolygonMesh& mesh) noexcept {
  if (const auto violation = CoordinateBoundViolation(mesh)) {
    return Error{ErrorCode::kInvalidInput, kCheckMeshStage, "mesh: " + *violation};
  }
  return CatchAll(kCheckMeshStage, [&] { return Check(mesh); });
}


Status RefuseBrokenSurface(const MeshValidity& v) {
  std::string classes;
  auto add = [&](bool broken, const std::string& what) {
    if (broken) classes += (classes.empty() ? "" : ", ") + what;
  };
  add(v.num_faces == 0, "no face");
  add(v.num_boundary_edges > 0, std::to_string(v.num_boundary_edges) + " boundary edges");
  add(v.num_non_manifold_edges > 0,
      std::to_string(v.num_non_manifold_edges) + " edges of more than two faces");
  add(!v.oriented && v.num_non_manifold_edges == 0, "faces not consistently oriented");
  add(v.num_degenerate_faces > 0, std::to_string(v.num_degenerate_faces) + " degenerate faces");
  add(v.num_non_planar_faces > 0, std::to_string(v.num_non_planar_faces) + " non-planar faces");
  add(v.self_intersecting, std::to_string(v.num_intersecting_triangle_pairs) +
                               " pairs of intersecting triangles");
  if (classes.empty()) return {};
  return Error{ErrorCode::kDegenerate, kCheckMeshStage,
               "the surface is not a valid boundary (" + classes +
                   "): a defect of linesurf, please report it with the input"};
}

std::vector<std::string> SolidValidityWarnings(const MeshValidity& v) {
  std::vector<std::string> warnings;
  if (v.num_coincident_vertices > 0) {
    warnings.push_back("mesh: " + std::to_string(v.num_coincident_vertices) +
                       " vertices at the position of another (parts touching there, split): "
                       "not one valid solid for GIS and BIM validators");
  }
  if (v.num_touching_triangle_pairs > 0) {
    warnings.push_back("mesh: " + std::to_string(v.num_touching_triangle_pairs) +
                       " pairs of triangles touching at a split vertex");
  }
  if (v.num_zero_area_faces > 0) {
    warnings.push_back("mesh: " + std::to_string(v.num_zero_area_faces) +
                       " faces of zero area (thinner than 1e-9 of the scene diagonal)");
  }
  return warnings;
}

}  // namespace linesurf
