#include "partition/mesh/triangle_tree.h"

#include "engine/core/exception.h"
#include "engine/core/face_triangulation.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include <boost/iterator/function_output_iterator.hpp>

namespace linesurf::partition {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 ToPoint(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
Vec3 ToVec(const Kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

struct TriangleTree::Impl {
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> triangle_face;
  Tree tree;

  [[nodiscard]] std::uint32_t Index(TriangleIterator t) const {
    return static_cast<std::uint32_t>(t - triangles.begin());
  }
};

TriangleTree::TriangleTree(const PolygonMesh& mesh, std::string_view stage, std::string_view name)
    : impl_(std::make_unique<Impl>()) {
  const std::string where(stage);
  LINESURF_THROW_IF(
      mesh.face_offsets.empty() || mesh.face_offsets.back() != mesh.face_indices.size(),
      kInvalidInput,
      where,
      name << " mesh: face offsets do not cover the indices");
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    for (const std::uint32_t v : face) {
      LINESURF_THROW_IF(v >= mesh.vertices.size(),
                        kInvalidInput,
                        where,
                        name << " mesh: face " << f << " refers to vertex " << v << " of "
                             << mesh.vertices.size());
    }
    for (const auto& [a, b, c] : FaceTriangles(mesh.vertices, face)) {
      const Triangle t(
          ToPoint(mesh.vertices[a]), ToPoint(mesh.vertices[b]), ToPoint(mesh.vertices[c]));
      if (t.is_degenerate()) continue;  // exact collinearity test; no area, never nearest
      impl_->triangles.push_back(t);
      impl_->triangle_face.push_back(static_cast<std::uint32_t>(f));
    }
  }
  LINESURF_THROW_IF(impl_->triangles.empty(),
                    kInvalidInput,
                    where,
                    name << " mesh has no face with positive area");
  impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
}

TriangleTree::~TriangleTree() = default;
TriangleTree::TriangleTree(TriangleTree&&) noexcept = default;
TriangleTree& TriangleTree::operator=(TriangleTree&&) noexcept = default;

std::size_t TriangleTree::NumTriangles() const { return impl_->triangles.size(); }

std::uint32_t TriangleTree::FaceOf(std::size_t t) const { return impl_->triangle_face[t]; }

std::array<Vec3, 3> TriangleTree::Corners(std::size_t t) const {
  const Triangle& tri = impl_->triangles[t];
  return {ToVec(tri.vertex(0)), ToVec(tri.vertex(1)), ToVec(tri.vertex(2))};
}

double TriangleTree::Area(std::size_t t) const {
  return std::sqrt(CGAL::to_double(impl_->triangles[t].squared_area()));
}

TriangleTree::Nearest TriangleTree::Closest(const Vec3& p) const {
  const Kernel::Point_3 q = ToPoint(p);
  const auto [closest, primitive] = impl_->tree.closest_point_and_primitive(q);
  return {
      ToVec(closest), CGAL::to_double(CGAL::squared_distance(closest, q)), impl_->Index(primitive)};
}

double TriangleTree::SquaredDistance(const Vec3& p) const {
  return CGAL::to_double(impl_->tree.squared_distance(ToPoint(p)));
}

bool TriangleTree::Intersects(const Vec3& a, const Vec3& b) const {
  return impl_->tree.do_intersect(Kernel::Segment_3(ToPoint(a), ToPoint(b)));
}

void TriangleTree::IntersectedTriangles(const Vec3& a,
                                        const Vec3& b,
                                        std::vector<std::uint32_t>& out) const {
  out.clear();
  impl_->tree.all_intersected_primitives(
      Kernel::Segment_3(ToPoint(a), ToPoint(b)),
      boost::make_function_output_iterator(
          [&](const TriangleIterator& t) { out.push_back(impl_->Index(t)); }));
}

}  // namespace linesurf::partition
