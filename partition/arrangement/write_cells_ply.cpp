#include "partition/arrangement/write_cells_ply.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>

#include "engine/core/exception.h"
#include "partition/arrangement/cell_geometry.h"

namespace linesurf::partition {
namespace {

constexpr char kWriteCellsPlyStage[] = "write_cells_ply";

template <typename T>
void Put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void Write(const CellComplex& cx, const std::filesystem::path& path, const CellsPlyOptions& options) {
  static_assert(std::endian::native == std::endian::little, "binary PLY writer assumes little endian");
  std::string vertices, faces;
  std::size_t num_vertices = 0, num_faces = 0;
  std::vector<VertexId> cell_vertices;
  for (std::size_t i = 0; i < cx.NumCells(); ++i) {
    const CellId c(i);
    cell_vertices = CellVertices(cx, c);
    const Vec3 centroid = CellCentroid(cx, c);
    const std::size_t base = num_vertices;
    for (const VertexId v : cell_vertices) {
      const Vec3 p = centroid + options.shrink * (cx.vertex_points[v] - centroid) + options.translation;
      for (int a = 0; a < 3; ++a) Put(vertices, static_cast<float>(p[a]));
      ++num_vertices;
    }
    const bool positive = cx.cell_colour[c] > 0;
    for (const FacetId f : cx.cell_facets[c]) {
      const auto cycle = OutwardFacetCycle(cx, f, c);
      LINESURF_THROW_IF(cycle.size() > 255,
                        kInvalidInput,
                        kWriteCellsPlyStage,
                        "facet with more than 255 vertices");
      Put(faces, static_cast<std::uint8_t>(cycle.size()));
      for (const VertexId v : cycle) {
        const auto local = std::lower_bound(cell_vertices.begin(), cell_vertices.end(), v) -
                           cell_vertices.begin();
        Put(faces, static_cast<std::int32_t>(base + static_cast<std::size_t>(local)));
      }
      Put(faces, static_cast<std::int32_t>(i));
      Put(faces, static_cast<std::uint8_t>(positive ? 230 : 60));
      Put(faces, static_cast<std::uint8_t>(positive ? 140 : 120));
      Put(faces, static_cast<std::uint8_t>(positive ? 40 : 220));
      ++num_faces;
    }
  }
  std::ofstream out(path, std::ios::binary);
  LINESURF_THROW_IF(!out, kInvalidInput, kWriteCellsPlyStage, "cannot open " << path.string());
  out << "ply\nformat binary_little_endian 1.0\ncomment linesurf cell complex, cells shrunk by "
      << options.shrink << "\nelement vertex " << num_vertices
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << num_faces
      << "\nproperty list uchar int vertex_indices\nproperty int cell\nproperty uchar red\n"
         "property uchar green\nproperty uchar blue\nend_header\n";
  out.write(vertices.data(), static_cast<std::streamsize>(vertices.size()));
  out.write(faces.data(), static_cast<std::streamsize>(faces.size()));
  LINESURF_THROW_IF(!out, kInvalidInput, kWriteCellsPlyStage, "cannot write " << path.string());
}

}  // namespace

Status CellsPlyOptions::Validate() const {
  if (!(shrink > 0 && shrink <= 1))
    return Error{ErrorCode::kInvalidOptions, kWriteCellsPlyStage, "shrink must be in (0, 1]"};
  if (!translation.allFinite())
    return Error{ErrorCode::kInvalidOptions, kWriteCellsPlyStage, "translation must be finite"};
  return {};
}

Status WriteCellsPly(const CellComplex& complex, const std::filesystem::path& path,
                     const CellsPlyOptions& options) noexcept {
  if (Status ok = options.Validate(); !ok) return ok;
  return CatchAll(kWriteCellsPlyStage, [&] { Write(complex, path, options); });
}

}  // namespace linesurf::partition
