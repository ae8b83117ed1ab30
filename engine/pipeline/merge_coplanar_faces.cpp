#include "engine/pipeline/merge_coplanar_faces.h"

#include "engine/core/disjoint_sets.h"

#include <algorithm>
#include <utility>

namespace linesurf::pipeline {
namespace {

/// The boundary of a group of faces as one cycle of old corners, or empty when the union is not
/// one simple polygon whose dropped vertices are its own.
std::vector<std::uint32_t> TraceBoundary(const SurfaceCycles& s,
                                         const std::vector<std::uint32_t>& members,
                                         const std::vector<std::uint32_t>& group_of_face,
                                         const std::vector<SurfaceEdgeId>& join_edges,
                                         const std::vector<std::uint32_t>& uses) {
  const auto is_join = [&](SurfaceEdgeId e) {
    return std::binary_search(join_edges.begin(), join_edges.end(), e);
  };
  const std::uint32_t group = group_of_face[members.front()];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> starts;  // (vertex, boundary corner)
  std::vector<std::uint32_t> vertices;                          // every corner's vertex
  for (const std::uint32_t f : members) {
    for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) {
      vertices.push_back(s.corner_vertex[k]);
      if (is_join(s.corner_edge[k])) continue;
      if (!s.partner[k].IsValid() || group_of_face[s.partner[k].index()] == group) {
        return {};  // unpaired (the back end reports it), or members meeting across a non-join
      }
      starts.push_back({s.corner_vertex[k], k});
    }
  }
  std::sort(starts.begin(), starts.end());
  for (std::size_t i = 1; i < starts.size(); ++i) {
    if (starts[i].first == starts[i - 1].first) return {};  // the boundary pinches
  }
  // A vertex that no boundary corner starts from lies inside the union: it may be dropped only
  // when no face outside the group uses it.
  std::sort(vertices.begin(), vertices.end());
  for (std::size_t i = 0; i < vertices.size();) {
    std::size_t j = i;
    while (j < vertices.size() && vertices[j] == vertices[i]) ++j;
    const auto start = std::lower_bound(
        starts.begin(), starts.end(), std::make_pair(vertices[i], std::uint32_t{0}));
    const bool on_boundary = start != starts.end() && start->first == vertices[i];
    if (!on_boundary && uses[vertices[i]] != j - i) return {};
    i = j;
  }
  const auto face_of = [&](std::uint32_t k) {
    return SurfaceFaceId(static_cast<std::uint32_t>(
        std::upper_bound(s.offsets.begin(), s.offsets.end(), k) - s.offsets.begin() - 1));
  };
  std::vector<std::uint32_t> cycle;
  std::uint32_t first =
      std::min_element(starts.begin(), starts.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->second;
  std::uint32_t k = first;
  do {
    cycle.push_back(k);
    const std::uint32_t end = s.corner_vertex[s.NextCorner(face_of(k), k)];
    const auto next =
        std::lower_bound(starts.begin(), starts.end(), std::make_pair(end, std::uint32_t{0}));
    if (next == starts.end() || next->first != end || cycle.size() > starts.size()) return {};
    k = next->second;
  } while (k != first);
  if (cycle.size() != starts.size()) return {};  // several boundary cycles: a hole
  return cycle;
}

}  // namespace

MergedCycles MergeAcrossJoins(const SurfaceCycles& s,
                              std::span<const FlatJoin> joins,
                              std::span<const EdgePair> crowded,
                              std::size_t num_vertices) {
  const std::size_t num_faces = s.NumFaces();
  DisjointSets sets(num_faces);
  std::vector<SurfaceEdgeId> join_edges;
  for (const FlatJoin& j : joins) {
    sets.Union(j.a.index(), j.b.index());
    join_edges.push_back(j.edge);
  }
  std::sort(join_edges.begin(), join_edges.end());
  std::vector<std::uint32_t> uses(num_vertices, 0);
  for (const std::uint32_t v : s.corner_vertex) ++uses[v];
  std::vector<std::uint32_t> group_of_face(num_faces);
  std::vector<std::vector<std::uint32_t>> members(num_faces);
  for (std::uint32_t f = 0; f < num_faces; ++f) {
    group_of_face[f] = static_cast<std::uint32_t>(sets.Find(f));
    members[group_of_face[f]].push_back(f);
  }
  // Boundary cycle of every group that merges.
  std::vector<std::vector<std::uint32_t>> boundary(num_faces);
  for (std::uint32_t g = 0; g < num_faces; ++g) {
    if (members[g].size() > 1) {
      boundary[g] = TraceBoundary(s, members[g], group_of_face, join_edges, uses);
    }
  }
  MergedCycles out;
  std::vector<SurfaceFaceId> new_face(num_faces);
  for (std::uint32_t f = 0; f < num_faces; ++f) {
    const std::uint32_t g = group_of_face[f];
    if (!boundary[g].empty() && f != members[g].front()) {
      new_face[f] = new_face[members[g].front()];
      continue;
    }
    new_face[f] = SurfaceFaceId(out.first_face.size());
    out.first_face.push_back(f);
  }
  SurfaceCycles& c = out.cycles;
  const auto add_corner = [&](std::uint32_t k) {
    c.corner_vertex.push_back(s.corner_vertex[k]);
    c.corner_edge.push_back(s.corner_edge[k]);
    c.partner.push_back(s.partner[k].IsValid() ? new_face[s.partner[k].index()]
                                               : SurfaceFaceId::Invalid());
  };
  for (const std::uint32_t f : out.first_face) {
    const std::uint32_t g = group_of_face[f];
    if (!boundary[g].empty()) {
      for (const std::uint32_t k : boundary[g]) add_corner(k);
      out.merged_faces += members[g].size();
    } else {
      for (std::uint32_t k = s.offsets[f]; k < s.offsets[f + 1]; ++k) add_corner(k);
    }
    c.offsets.push_back(static_cast<std::uint32_t>(c.corner_vertex.size()));
  }
  for (const EdgePair& p : crowded) {
    out.crowded.push_back({p.edge, new_face[p.a.index()], new_face[p.b.index()]});
  }
  return out;
}

}  // namespace linesurf::pipeline
