#pragma once
// A polygon mesh (convex faces by default) as plain data, shared by writers, readers and checks.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/geometry.h"
#include "engine/core/strong_id.h"

namespace linesurf {

/// A vertex of a PolygonMesh (an index into `vertices`; the face lists store its value).
struct MeshVertexTag {};
using MeshVertexId = StrongId<MeshVertexTag>;

struct PolygonMesh {
  std::vector<Vec3> vertices;
  /// Face f uses face_indices[face_offsets[f] .. face_offsets[f+1]), counter-clockwise seen from
  /// outside (the normal points from full to empty space).
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;

  [[nodiscard]] std::size_t NumFaces() const { return face_offsets.size() - 1; }
  [[nodiscard]] std::span<const std::uint32_t> Face(std::size_t f) const {
    return {face_indices.data() + face_offsets[f], face_indices.data() + face_offsets[f + 1]};
  }
  void AddFace(std::span<const std::uint32_t> face) {
    face_indices.insert(face_indices.end(), face.begin(), face.end());
    face_offsets.push_back(static_cast<std::uint32_t>(face_indices.size()));
  }
};

}  // namespace linesurf
