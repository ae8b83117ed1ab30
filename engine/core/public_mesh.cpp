#include "engine/core/public_mesh.h"

#include "engine/core/exception.h"

#include <string>

namespace linesurf {

Mesh ToMesh(const PolygonMesh& mesh) {
  Mesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) out.vertices.push_back(Vector3{v.x(), v.y(), v.z()});
  out.face_offsets = mesh.face_offsets;
  out.face_indices = mesh.face_indices;
  return out;
}

Expected<PolygonMesh> ToPolygonMesh(const Mesh& mesh) {
  const auto bad = [](const std::string& why) -> Error {
    return Error{ErrorCode::kInvalidInput, "mesh", why};
  };
  if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0) {
    return bad("face_offsets must start with 0");
  }
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f) {
    if (mesh.face_offsets[f + 1] < mesh.face_offsets[f]) {
      return bad("face_offsets[" + std::to_string(f + 1) + "] is smaller than the one before");
    }
  }
  if (mesh.face_offsets.back() != mesh.face_indices.size()) {
    return bad("the last face offset (" + std::to_string(mesh.face_offsets.back()) +
               ") is not the number of face indices (" + std::to_string(mesh.face_indices.size()) +
               ")");
  }
  return CatchAll("mesh", [&]() -> PolygonMesh {
    PolygonMesh out;
    out.vertices.reserve(mesh.vertices.size());
    for (const Vector3& v : mesh.vertices) out.vertices.push_back(Vec3(v[0], v[1], v[2]));
    out.face_offsets = mesh.face_offsets;
    out.face_indices = mesh.face_indices;
    return out;
  });
}

}  // namespace linesurf
