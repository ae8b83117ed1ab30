#include "tools/cli/mesh_validity_json.h"

namespace linesurf::cli {

nlohmann::json MeshValidityJson(const MeshValidity& v) {
  return {{"valid", v.IsValid()},
          {"closed", v.closed},
          {"two_manifold", v.two_manifold},
          {"oriented", v.oriented},
          {"outward", v.outward},
          {"self_intersecting", v.self_intersecting},
          {"num_components", v.num_components},
          {"num_faces", v.num_faces},
          {"num_vertices", v.num_vertices},
          {"num_coincident_vertices", v.num_coincident_vertices},
          {"num_boundary_edges", v.num_boundary_edges},
          {"num_non_manifold_edges", v.num_non_manifold_edges},
          {"num_non_manifold_vertices", v.num_non_manifold_vertices},
          {"num_degenerate_faces", v.num_degenerate_faces},
          {"num_zero_area_faces", v.num_zero_area_faces},
          {"num_non_planar_faces", v.num_non_planar_faces},
          {"num_intersecting_triangle_pairs", v.num_intersecting_triangle_pairs},
          {"num_touching_triangle_pairs", v.num_touching_triangle_pairs},
          {"signed_volume", v.signed_volume}};
}

}  // namespace linesurf::cli
