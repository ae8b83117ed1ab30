#include "engine/io/vertex_groups_write.h"

#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/number_text.h"

#include <string>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kVertexGroupsWriteStage = "write_vg";

void AppendVec(std::string& out, const Vec3& v, const std::string& file) {
  LINESURF_THROW_IF(!v.allFinite(),
                    kInvalidInput,
                    kVertexGroupsWriteStage,
                    file << ": a non-finite coordinate cannot be written");
  for (int k = 0; k < 3; ++k) {
    if (k) out += ' ';
    AppendDouble(out, v[k]);
  }
  out += '\n';
}

}  // namespace

Status WriteVertexGroups(const Scene& scene, const std::filesystem::path& path) noexcept {
  return CatchAll(kVertexGroupsWriteStage, [&] {
    const std::string file = path.string();
    const std::size_t n = scene.segments.size();
    const Rigid3& frame = scene.world_from_local;
    const bool has_memberships = scene.HasMemberships();
    auto membership = [&](std::size_t i) {
      return has_memberships ? scene.memberships[SegmentId(i)] : PlaneMembership{};
    };
    std::string out;
    out += "num_points: ";
    AppendUnsigned(out, 2 * n);
    out += '\n';
    for (const Segment3& s : scene.segments) {
      AppendVec(out, frame.Apply(s.p1), file);
      AppendVec(out, frame.Apply(s.p2), file);
    }
    out += "num_colors: ";
    AppendUnsigned(out, 2 * n);
    out += '\n';
    for (std::size_t i = 0; i < 2 * n; ++i) out += "0.5 0.5 0.5\n";
    out += "num_normals: ";
    AppendUnsigned(out, 2 * n);
    out += '\n';
    std::vector<std::vector<std::size_t>> groups(scene.planes.size());
    for (std::size_t i = 0; i < n; ++i) {
      const PlaneMembership m = membership(i);
      const Vec3 normal =
          m.count > 0 ? frame.Rotate(scene.planes[m.planes[0]].normal) : Vec3::Zero();
      AppendVec(out, normal, file);
      AppendVec(out, normal, file);
      for (std::uint8_t k = 0; k < m.count; ++k) groups[m.planes[k].index()].push_back(i);
    }
    out += "num_groups: ";
    AppendUnsigned(out, groups.size());
    out += '\n';
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const Plane3& plane = scene.planes[PlaneId(g)];
      const Vec3 normal = frame.Rotate(plane.normal);
      const double d = -normal.dot(frame.Apply(plane.point));
      out += "group_type: 0\nnum_group_parameters: 4\ngroup_parameters: ";
      for (int k = 0; k < 3; ++k) {
        AppendDouble(out, normal[k]);
        out += ' ';
      }
      AppendDouble(out, d);
      out += "\ngroup_label: plane_";
      AppendUnsigned(out, g);
      out += "\ngroup_color: 0.5 0.5 0.5\ngroup_num_point: ";
      AppendUnsigned(out, 2 * groups[g].size());
      out += '\n';
      for (std::size_t k = 0; k < groups[g].size(); ++k) {
        if (k) out += ' ';
        AppendUnsigned(out, 2 * groups[g][k]);
        out += ' ';
        AppendUnsigned(out, 2 * groups[g][k] + 1);
      }
      out += "\nnum_children: 0\n";
    }
    WriteFileAtomically(path, out, kVertexGroupsWriteStage);
  });
}

}  // namespace linesurf::io
