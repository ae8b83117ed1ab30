#include "tools/gen/solid_model.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

#include "engine/core/exception.h"

namespace linesurf::synth {
namespace {

/// Plane keys are rounded to this resolution (unit normal components and metres): synthetic
/// planes are either identical or far apart.
constexpr double kPlaneKeyResolution = 1e-9;
/// Components below this magnitude do not decide the canonical sign of a normal.
constexpr double kSignEpsilon = 1e-12;
/// Collinear sharp-edge intervals closer than this (metres) are merged into one run.
constexpr double kMergeGap = 1e-9;

std::int64_t KeyOf(double value) { return std::llround(value / kPlaneKeyResolution); }

Vec3 NewellNormal(const SolidComponent& c, const SolidFace& f) {
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 0; i < f.vertices.size(); ++i) {
    const Vec3& a = c.vertices[f.vertices[i]];
    const Vec3& b = c.vertices[f.vertices[(i + 1) % f.vertices.size()]];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
              (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

}  // namespace

SolidModel::PlaneKey SolidModel::KeyOfPlane(const Vec3& normal, const Vec3& point) {
  Vec3 canonical = normal.normalized();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(canonical[a]) > kSignEpsilon) {
      if (canonical[a] < 0) canonical = -canonical;
      break;
    }
  }
  return {KeyOf(canonical.x()), KeyOf(canonical.y()), KeyOf(canonical.z()),
          KeyOf(-canonical.dot(point))};
}

PlaneId SolidModel::InternPlane(const Vec3& normal, const Vec3& point) {
  const PlaneKey key = KeyOfPlane(normal, point);
  const auto it = plane_index_.find(key);
  if (it != plane_index_.end()) return it->second;
  const PlaneId id = planes_.NextId();
  planes_.push_back(Plane3{point, normal.normalized()});
  plane_index_.emplace(key, id);
  return id;
}

PlaneId SolidModel::FindPlane(const Vec3& normal, const Vec3& point) const {
  const auto it = plane_index_.find(KeyOfPlane(normal, point));
  return it == plane_index_.end() ? PlaneId::Invalid() : it->second;
}

void SolidModel::AddComponent(SolidComponent component) {
  for (SolidFace& f : component.faces) {
    LINESURF_ASSERT(f.vertices.size() >= 3);
    const Vec3 n = NewellNormal(component, f);
    LINESURF_ASSERT(n.norm() > 0.0);
    f.outward = n.normalized();
    f.plane = InternPlane(f.outward, component.vertices[f.vertices[0]]);
  }
  components_.push_back(std::move(component));
}

void SolidModel::AddPrism(std::span<const Vec3> base, const Vec3& extrusion) {
  const auto n = static_cast<std::uint32_t>(base.size());
  SolidComponent c;
  for (const Vec3& p : base) c.vertices.push_back(p);
  for (const Vec3& p : base) c.vertices.push_back(p + extrusion);
  SolidFace bottom;  // reversed, still starting at base[0] (star centre)
  bottom.vertices.push_back(0);
  for (std::uint32_t i = n - 1; i >= 1; --i) bottom.vertices.push_back(i);
  c.faces.push_back(bottom);
  SolidFace top;
  for (std::uint32_t i = 0; i < n; ++i) top.vertices.push_back(n + i);
  c.faces.push_back(top);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    c.faces.push_back(SolidFace{{i, j, n + j, n + i}, PlaneId(), Vec3::UnitZ()});
  }
  AddComponent(std::move(c));
}

PolygonMesh SolidModel::ToPolygonMesh() const {
  PolygonMesh mesh;
  std::vector<std::uint32_t> face;
  for (const SolidComponent& c : components_) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const SolidFace& f : c.faces) {
      face.clear();
      for (std::uint32_t v : f.vertices) face.push_back(base + v);
      mesh.AddFace(face);
    }
  }
  return mesh;
}

std::vector<SharpEdge> SolidModel::SharpEdges() const {
  // Key: plane pair (sorted) and the orientation of each face relative to its plane.
  using RunKey = std::tuple<std::uint32_t, std::uint32_t, bool, bool>;
  struct Piece {
    double t0, t1;
    Vec3 foot;
  };
  struct Group {
    Vec3 dir;
    std::array<Vec3, 2> outward;
    std::vector<Piece> pieces;
  };
  std::map<RunKey, Group> groups;
  for (const SolidComponent& c : components_) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edge_faces;
    for (std::uint32_t fi = 0; fi < c.faces.size(); ++fi) {
      const auto& v = c.faces[fi].vertices;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::uint32_t a = v[i];
        const std::uint32_t b = v[(i + 1) % v.size()];
        edge_faces[{std::min(a, b), std::max(a, b)}].push_back(fi);
      }
    }
    for (const auto& [edge, faces] : edge_faces) {
      LINESURF_ASSERT(faces.size() == 2);
      const SolidFace* fa = &c.faces[faces[0]];
      const SolidFace* fb = &c.faces[faces[1]];
      if (fa->plane == fb->plane) continue;  // flat edge inside a split face
      if (fb->plane < fa->plane) std::swap(fa, fb);
      const Plane3& pa = planes_[fa->plane];
      const Plane3& pb = planes_[fb->plane];
      const RunKey key{fa->plane.value(), fb->plane.value(), fa->outward.dot(pa.normal) > 0,
                       fb->outward.dot(pb.normal) > 0};
      auto [it, inserted] = groups.try_emplace(key);
      Group& g = it->second;
      if (inserted) {
        g.dir = pa.normal.cross(pb.normal).normalized();
        g.outward = {fa->outward, fb->outward};
      }
      const Vec3& p = c.vertices[edge.first];
      const Vec3& q = c.vertices[edge.second];
      const double tp = g.dir.dot(p);
      const double tq = g.dir.dot(q);
      g.pieces.push_back(Piece{std::min(tp, tq), std::max(tp, tq), p - g.dir * tp});
    }
  }
  std::vector<SharpEdge> result;
  for (auto& [key, g] : groups) {
    std::sort(g.pieces.begin(), g.pieces.end(),
              [](const Piece& x, const Piece& y) { return x.t0 < y.t0; });
    const std::array<PlaneId, 2> planes = {PlaneId(std::get<0>(key)), PlaneId(std::get<1>(key))};
    std::size_t i = 0;
    while (i < g.pieces.size()) {
      const Vec3 foot = g.pieces[i].foot;
      const double t0 = g.pieces[i].t0;
      double t1 = g.pieces[i].t1;
      std::size_t j = i + 1;
      while (j < g.pieces.size() && g.pieces[j].t0 <= t1 + kMergeGap) {
        t1 = std::max(t1, g.pieces[j].t1);
        ++j;
      }
      result.push_back(SharpEdge{Segment3{foot + g.dir * t0, foot + g.dir * t1}, planes, g.outward});
      i = j;
    }
  }
  return result;
}

SolidComponent BoxesSolid(const AxisBox& outer, std::span<const AxisBox> cavities,
                          std::span<const AxisBox> additions) {
  std::array<std::vector<double>, 3> coords;
  for (std::span<const AxisBox> list : {cavities, additions}) {
    for (const AxisBox& b : list) {
      for (int a = 0; a < 3; ++a) {
        coords[a].push_back(b.min[a]);
        coords[a].push_back(b.max[a]);
      }
    }
  }
  for (int a = 0; a < 3; ++a) {
    coords[a].push_back(outer.min[a]);
    coords[a].push_back(outer.max[a]);
    std::sort(coords[a].begin(), coords[a].end());
    coords[a].erase(std::unique(coords[a].begin(), coords[a].end()), coords[a].end());
  }
  std::vector<std::uint8_t> full;
  for (std::size_t k = 0; k + 1 < coords[2].size(); ++k) {
    for (std::size_t j = 0; j + 1 < coords[1].size(); ++j) {
      for (std::size_t i = 0; i + 1 < coords[0].size(); ++i) {
        const Vec3 c(0.5 * (coords[0][i] + coords[0][i + 1]), 0.5 * (coords[1][j] + coords[1][j + 1]),
                     0.5 * (coords[2][k] + coords[2][k + 1]));
        const auto inside = [&](const AxisBox& b) { return b.Contains(c); };
        const bool in_cavity = std::any_of(cavities.begin(), cavities.end(), inside);
        const bool added = std::any_of(additions.begin(), additions.end(), inside);
        full.push_back((outer.Contains(c) && !in_cavity) || added ? 1 : 0);
      }
    }
  }
  return RectilinearSolid(coords, full);
}

SolidComponent RectilinearSolid(const std::array<std::vector<double>, 3>& coords,
                                const std::vector<std::uint8_t>& full) {
  const std::array<std::size_t, 3> nodes = {coords[0].size(), coords[1].size(), coords[2].size()};
  for (std::size_t n : nodes) LINESURF_ASSERT(n >= 2);
  const std::array<std::size_t, 3> cells = {nodes[0] - 1, nodes[1] - 1, nodes[2] - 1};
  LINESURF_ASSERT(full.size() == cells[0] * cells[1] * cells[2]);
  const auto is_full = [&](std::array<std::ptrdiff_t, 3> c) {
    for (int a = 0; a < 3; ++a) {
      if (c[a] < 0 || c[a] >= static_cast<std::ptrdiff_t>(cells[a])) return false;
    }
    return full[static_cast<std::size_t>(c[0]) +
                cells[0] * (static_cast<std::size_t>(c[1]) +
                            cells[1] * static_cast<std::size_t>(c[2]))] != 0;
  };
  SolidComponent out;
  std::vector<std::int64_t> vertex_of(nodes[0] * nodes[1] * nodes[2], -1);
  const auto vertex = [&](std::array<std::size_t, 3> n) {
    std::int64_t& id = vertex_of[n[0] + nodes[0] * (n[1] + nodes[1] * n[2])];
    if (id < 0) {
      id = static_cast<std::int64_t>(out.vertices.size());
      out.vertices.emplace_back(coords[0][n[0]], coords[1][n[1]], coords[2][n[2]]);
    }
    return static_cast<std::uint32_t>(id);
  };
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    for (std::size_t i = 0; i < nodes[a]; ++i) {
      for (std::size_t k = 0; k < cells[c]; ++k) {
        for (std::size_t j = 0; j < cells[b]; ++j) {
          std::array<std::ptrdiff_t, 3> below{};
          below[a] = static_cast<std::ptrdiff_t>(i) - 1;
          below[b] = static_cast<std::ptrdiff_t>(j);
          below[c] = static_cast<std::ptrdiff_t>(k);
          std::array<std::ptrdiff_t, 3> above = below;
          above[a] += 1;
          const bool full_below = is_full(below);
          if (full_below == is_full(above)) continue;
          std::array<std::array<std::size_t, 3>, 4> corner{};
          const std::size_t jb[4] = {j, j + 1, j + 1, j};
          const std::size_t kc[4] = {k, k, k + 1, k + 1};
          for (int q = 0; q < 4; ++q) {
            corner[q][a] = i;
            corner[q][b] = jb[q];
            corner[q][c] = kc[q];
          }
          SolidFace f;
          // e_b x e_c = e_a: this order faces +a, i.e. from a full cell below to empty above.
          for (int q = 0; q < 4; ++q) f.vertices.push_back(vertex(corner[full_below ? q : 3 - q]));
          out.faces.push_back(std::move(f));
        }
      }
    }
  }
  return out;
}

}  // namespace linesurf::synth
