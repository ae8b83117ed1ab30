#include "tools/gen/occluder.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace linesurf::synth {
namespace {

/// Crossings closer than this to the target (metres) belong to the target's own faces.
constexpr double kTargetGap = 1e-7;
/// Crossings closer than this to the eye (parameter along the ray) are ignored.
constexpr double kEyeGap = 1e-12;
/// Barycentric slack: rays through an edge shared by two triangles hit at least one of them.
constexpr double kBarycentricSlack = 1e-9;
/// Rays closer to parallel than this (sine of the angle) to a triangle do not cross it.
constexpr double kParallelSine = 1e-12;
/// Triangles per culling group (each group has its own bounding box).
constexpr std::size_t kTrianglesPerGroup = 32;
/// The grid never has more than this many cells per axis.
constexpr double kMaxCellsPerAxis = 1024.0;

}  // namespace

Occluder::Occluder(const SolidModel& model) {
  Box3 all;
  // Groups of at most kTrianglesPerGroup consecutive triangles of one component: builders emit
  // faces in spatially coherent order, so the group boxes cull well (room grids, buildings).
  for (const SolidComponent& c : model.components()) {
    std::vector<Triangle> component_triangles;
    for (const SolidFace& f : c.faces) {
      const Vec3& a = c.vertices[f.vertices[0]];
      for (std::size_t i = 1; i + 1 < f.vertices.size(); ++i) {
        component_triangles.push_back(Triangle{a, c.vertices[f.vertices[i]] - a,
                                               c.vertices[f.vertices[i + 1]] - a});
      }
    }
    for (std::size_t first = 0; first < component_triangles.size(); first += kTrianglesPerGroup) {
      const std::size_t last = std::min(first + kTrianglesPerGroup, component_triangles.size());
      Group g;
      g.first = static_cast<std::uint32_t>(triangles_.size());
      for (std::size_t t = first; t < last; ++t) {
        const Triangle& tr = component_triangles[t];
        g.box.Extend(tr.a);
        g.box.Extend(tr.a + tr.e1);
        g.box.Extend(tr.a + tr.e2);
        triangles_.push_back(tr);
      }
      g.last = static_cast<std::uint32_t>(triangles_.size());
      all.Extend(g.box.min);
      all.Extend(g.box.max);
      groups_.push_back(g);
    }
  }
  if (groups_.empty()) return;
  double largest = 0.0;
  for (const Group& g : groups_) {
    largest = std::max({largest, g.box.Extent().x(), g.box.Extent().y()});
  }
  const Vec3 extent = all.Extent();
  cell_ = std::max({largest, extent.x() / kMaxCellsPerAxis, extent.y() / kMaxCellsPerAxis,
                    kTargetGap});
  origin_x_ = all.min.x();
  origin_y_ = all.min.y();
  nx_ = static_cast<std::int64_t>(std::floor(extent.x() / cell_)) + 1;
  ny_ = static_cast<std::int64_t>(std::floor(extent.y() / cell_)) + 1;
  const auto cell_range = [&](const Box3& box, std::int64_t& i0, std::int64_t& i1,
                              std::int64_t& j0, std::int64_t& j1) {
    i0 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((box.min.x() - origin_x_) / cell_)), 0, nx_ - 1);
    i1 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((box.max.x() - origin_x_) / cell_)), 0, nx_ - 1);
    j0 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((box.min.y() - origin_y_) / cell_)), 0, ny_ - 1);
    j1 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((box.max.y() - origin_y_) / cell_)), 0, ny_ - 1);
  };
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  for (const Group& g : groups_) {
    std::int64_t i0, i1, j0, j1;
    cell_range(g.box, i0, i1, j0, j1);
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) ++counts[static_cast<std::size_t>(i + nx_ * j) + 1];
  }
  cell_offsets_.assign(counts.size(), 0);
  for (std::size_t c = 1; c < counts.size(); ++c) cell_offsets_[c] = cell_offsets_[c - 1] + counts[c];
  cell_items_.resize(cell_offsets_.back());
  std::vector<std::uint32_t> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
  for (std::uint32_t gi = 0; gi < groups_.size(); ++gi) {
    std::int64_t i0, i1, j0, j1;
    cell_range(groups_[gi].box, i0, i1, j0, j1);
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) cell_items_[fill[static_cast<std::size_t>(i + nx_ * j)]++] = gi;
  }
}

bool Occluder::HitsGroup(const Group& g, const Vec3& eye, const Vec3& dir, double t_max) const {
  // Slab test against the group's box first.
  double t0 = 0.0;
  double t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0) {
      if (eye[a] < g.box.min[a] || eye[a] > g.box.max[a]) return false;
      continue;
    }
    const double inv = 1.0 / dir[a];
    double ta = (g.box.min[a] - eye[a]) * inv;
    double tb = (g.box.max[a] - eye[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  const double dir_norm = dir.norm();
  for (std::uint32_t ti = g.first; ti < g.last; ++ti) {
    const Triangle& tr = triangles_[ti];
    const Vec3 p = dir.cross(tr.e2);
    const double det = tr.e1.dot(p);
    if (std::abs(det) <= kParallelSine * dir_norm * tr.e1.cross(tr.e2).norm()) continue;
    const double inv = 1.0 / det;
    const Vec3 s = eye - tr.a;
    const double u = s.dot(p) * inv;
    if (u < -kBarycentricSlack || u > 1.0 + kBarycentricSlack) continue;
    const Vec3 q = s.cross(tr.e1);
    const double v = dir.dot(q) * inv;
    if (v < -kBarycentricSlack || u + v > 1.0 + kBarycentricSlack) continue;
    const double t = tr.e2.dot(q) * inv;
    if (t > kEyeGap && t < t_max) return true;
  }
  return false;
}

bool Occluder::IsClear(const Vec3& eye, const Vec3& target,
                       std::vector<std::uint32_t>& scratch) const {
  if (groups_.empty()) return true;
  const Vec3 dir = target - eye;
  const double length = dir.norm();
  if (length <= kTargetGap) return true;
  const double t_max = 1.0 - kTargetGap / length;
  const auto cell_of = [&](double v, double origin, std::int64_t n) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((v - origin) / cell_)), 0,
                                    n - 1);
  };
  const std::int64_t i0 = cell_of(std::min(eye.x(), target.x()), origin_x_, nx_);
  const std::int64_t i1 = cell_of(std::max(eye.x(), target.x()), origin_x_, nx_);
  const std::int64_t j0 = cell_of(std::min(eye.y(), target.y()), origin_y_, ny_);
  const std::int64_t j1 = cell_of(std::max(eye.y(), target.y()), origin_y_, ny_);
  std::vector<std::uint32_t>& candidates = scratch;
  candidates.clear();
  for (std::int64_t j = j0; j <= j1; ++j) {
    for (std::int64_t i = i0; i <= i1; ++i) {
      const auto c = static_cast<std::size_t>(i + nx_ * j);
      candidates.insert(candidates.end(), cell_items_.begin() + cell_offsets_[c],
                        cell_items_.begin() + cell_offsets_[c + 1]);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (std::uint32_t gi : candidates) {
    if (HitsGroup(groups_[gi], eye, dir, t_max)) return false;
  }
  return true;
}

}  // namespace linesurf::synth
