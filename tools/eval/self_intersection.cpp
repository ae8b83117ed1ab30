#include "tools/eval/self_intersection.h"

#include "engine/core/public_mesh.h"
#include "tools/eval/mesh_topology.h"

namespace linesurf {

Expected<bool> IntersectsItself(const Mesh& mesh) noexcept {
  Expected<PolygonMesh> engine_mesh = ToPolygonMesh(mesh);
  if (!engine_mesh) return engine_mesh.error();
  Expected<MeshTopology> topology = CheckMeshTopology(*engine_mesh);
  if (!topology) return topology.error();
  return topology->self_intersecting;
}

}  // namespace linesurf
