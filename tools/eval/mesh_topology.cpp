#include "tools/eval/mesh_topology.h"

#include "engine/core/coordinate_bound.h"
#include "engine/core/disjoint_sets.h"
#include "engine/core/exception.h"
#include "engine/core/vector_area.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>
#include <vector>

namespace linesurf {
namespace {

constexpr const char* kMeshTopologyStage = "check_mesh_topology";

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

bool SelfIntersects(const PolygonMesh& mesh, const std::vector<std::vector<std::size_t>>& faces) {
  if (faces.empty()) return false;
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
                    kMeshTopologyStage,
                    "a face could not be triangulated for the self-intersection test");
  using Face = CgalMesh::Face_index;
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(CGAL::faces(cgal_mesh), cgal_mesh, std::back_inserter(pairs));
  // Faces that meet at a common position without sharing the vertex (split non-manifold
  // vertices, coincident copies) touch there; CGAL reports them, we do not count them.
  const auto corners = [&](Face f) {
    std::vector<Kernel::Point_3> out;
    for (auto v : CGAL::vertices_around_face(cgal_mesh.halfedge(f), cgal_mesh)) {
      out.push_back(cgal_mesh.point(v));
    }
    return out;
  };
  for (const auto& [f, g] : pairs) {
    bool touching = false;
    for (const auto& p : corners(f)) {
      for (const auto& q : corners(g)) touching = touching || p == q;
    }
    if (!touching) return true;
  }
  return false;
}

MeshTopology Check(const PolygonMesh& mesh) {
  const std::size_t num_vertices = mesh.vertices.size();
  LINESURF_THROW_IF(mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 ||
                        mesh.face_offsets.back() != mesh.face_indices.size(),
                    kInvalidInput,
                    kMeshTopologyStage,
                    "face offsets do not cover the face indices");
  for (std::size_t i = 0; i < mesh.face_indices.size(); ++i) {
    LINESURF_THROW_IF(mesh.face_indices[i] >= num_vertices,
                      kInvalidInput,
                      kMeshTopologyStage,
                      "face index " << i << " refers to vertex " << mesh.face_indices[i] << " of "
                                    << num_vertices);
  }
  MeshTopology topo;
  topo.num_faces = mesh.NumFaces();
  topo.num_vertices = mesh.vertices.size();
  topo.num_coincident_vertices = CountCoincidentVertices(mesh);

  // Faces by vertex index; those with fewer than 3 distinct vertices or a repeated vertex are degenerate
  // and take no part in the checks.
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

  // Area and signed volume over a fan triangulation: a planar face's area is the length of the
  // sum of its fan's vector areas, convex or not (merged faces are not), and the volume is exact
  // for any closed polygon mesh because the fan's inner edges cancel.
  for (const auto& face : faces) {
    const Vec3& a = mesh.vertices[face[0]];
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      topo.signed_volume += a.dot(mesh.vertices[face[k]].cross(mesh.vertices[face[k + 1]])) / 6.0;
    }
    topo.area += 0.5 * TwiceVectorArea(face.size(), [&](std::size_t k) -> const Vec3& {
                         return mesh.vertices[face[k]];
                       }).norm();
  }

  // Directed edges (lo, hi, forward, face) sorted: groups are undirected edges.
  struct HalfEdge {
    std::size_t lo, hi;
    bool forward;
    std::size_t face;
    auto Key() const { return std::tie(lo, hi, forward, face); }
  };
  std::vector<HalfEdge> edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::size_t a = face[k];
      const std::size_t b = face[(k + 1) % face.size()];
      edges.push_back({std::min(a, b), std::max(a, b), a < b, f});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return x.Key() < y.Key(); });
  DisjointSets face_sets(faces.size());
  bool consistent = true;
  std::size_t group = 0;  // first half-edge of the current undirected edge
  for (std::size_t i = 1; i <= edges.size() && !edges.empty(); ++i) {
    if (i < edges.size() && edges[i].lo == edges[group].lo && edges[i].hi == edges[group].hi) {
      face_sets.Union(edges[group].face, edges[i].face);
      continue;
    }
    const std::size_t uses = i - group;
    if (uses == 1) ++topo.num_boundary_edges;
    if (uses > 2) ++topo.num_non_manifold_edges;
    if (uses == 2 && edges[group].forward == edges[group + 1].forward) consistent = false;
    group = i;
  }
  topo.num_components = face_sets.CountRoots(faces.size());

  // Vertex fans: corners around a vertex are linked when they share an edge to a neighbour x.
  struct Corner {
    std::size_t vertex, neighbour, corner;
  };
  std::vector<Corner> links;
  std::size_t num_corners = 0;
  for (const auto& face : faces) {
    for (std::size_t k = 0; k < face.size(); ++k, ++num_corners) {
      const std::size_t prev = face[(k + face.size() - 1) % face.size()];
      const std::size_t next = face[(k + 1) % face.size()];
      links.push_back({face[k], prev, num_corners});
      links.push_back({face[k], next, num_corners});
    }
  }
  std::sort(links.begin(), links.end(), [](const Corner& x, const Corner& y) {
    return std::tie(x.vertex, x.neighbour, x.corner) < std::tie(y.vertex, y.neighbour, y.corner);
  });
  DisjointSets corner_sets(num_corners);
  for (std::size_t i = 0; i + 1 < links.size(); ++i) {
    if (links[i].vertex == links[i + 1].vertex && links[i].neighbour == links[i + 1].neighbour) {
      corner_sets.Union(links[i].corner, links[i + 1].corner);
    }
  }
  for (std::size_t i = 0; i < links.size();) {
    std::size_t j = i;
    std::size_t fans = 0;
    std::vector<std::size_t> roots;
    while (j < links.size() && links[j].vertex == links[i].vertex) {
      roots.push_back(corner_sets.Find(links[j].corner));
      ++j;
    }
    std::sort(roots.begin(), roots.end());
    fans = static_cast<std::size_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
    if (fans > 1) ++topo.num_non_manifold_vertices;
    i = j;
  }

  topo.closed = !faces.empty() && topo.num_boundary_edges == 0 && topo.num_non_manifold_edges == 0;
  topo.two_manifold = topo.num_non_manifold_edges == 0 && topo.num_non_manifold_vertices == 0;
  topo.oriented = consistent && topo.num_non_manifold_edges == 0;
  topo.outward = topo.closed && topo.oriented && topo.signed_volume > 0.0;
  topo.self_intersecting = SelfIntersects(mesh, faces);
  return topo;
}

}  // namespace

Expected<MeshTopology> CheckMeshTopology(const PolygonMesh& mesh) noexcept {
  if (const auto violation = CoordinateBoundViolation(mesh)) {
    return Error{ErrorCode::kInvalidInput, kMeshTopologyStage, "mesh: " + *violation};
  }
  return CatchAll(kMeshTopologyStage, [&] { return Check(mesh); });
}

}  // namespace linesurf
