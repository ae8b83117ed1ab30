// Mesh writers: PLY (binary little-endian or ASCII), OBJ, OFF.

#include "engine/core/exception.h"
#include "engine/core/face_triangulation.h"
#include "engine/io/file_access.h"
#include "engine/io/mesh_format.h"
#include "engine/io/mesh_io.h"
#include "engine/io/number_text.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace linesurf::io {
namespace {

constexpr const char* kMeshWriteStage = "write_mesh";

/// The faces to write: the mesh's own, or their triangle fans.
struct FaceList {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  std::size_t max_size = 0;

  void Add(std::initializer_list<std::uint32_t> face) {
    indices.insert(indices.end(), face.begin(), face.end());
    offsets.push_back(static_cast<std::uint32_t>(indices.size()));
    max_size = std::max(max_size, face.size());
  }
  [[nodiscard]] std::size_t Count() const { return offsets.size() - 1; }
};

FaceList CheckedFaces(const PolygonMesh& mesh, const MeshWriteOptions& options,
                      const std::string& file) {
  LINESURF_THROW_IF(
      mesh.face_offsets.empty() || mesh.face_offsets.back() != mesh.face_indices.size(),
      kInvalidInput,
      kMeshWriteStage,
      file << ": mesh face offsets do not match its indices");
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    LINESURF_THROW_IF(!mesh.vertices[v].allFinite(),
                      kInvalidInput,
                      kMeshWriteStage,
                      file << ": vertex " << v << " has a non-finite coordinate");
  }
  FaceList faces;
  faces.indices.reserve(mesh.face_indices.size() * (options.triangulate ? 3 : 1));
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    LINESURF_THROW_IF(
        face.size() < 3,
        kInvalidInput,
        kMeshWriteStage,
        file << ": face " << f << " has " << face.size() << " vertices (at least 3 needed)");
    for (const std::uint32_t i : face) {
      LINESURF_THROW_IF(
          i >= mesh.vertices.size(),
          kInvalidInput,
          kMeshWriteStage,
          file << ": face " << f << " uses vertex " << i << " of " << mesh.vertices.size());
    }
    if (options.triangulate) {
      for (const auto& [a, b, c] : FaceTriangles(mesh.vertices, face)) faces.Add({a, b, c});
    } else {
      faces.indices.insert(faces.indices.end(), face.begin(), face.end());
      faces.offsets.push_back(static_cast<std::uint32_t>(faces.indices.size()));
      faces.max_size = std::max(faces.max_size, face.size());
    }
  }
  return faces;
}

template <typename T>
void AppendLittleEndian(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little, "big-endian hosts not supported");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string PlyText(const PolygonMesh& mesh, const FaceList& faces, bool ascii) {
  // Faces of up to 255 vertices use a uchar count (what most viewers expect), longer ones uint.
  const bool small_faces = faces.max_size <= 255;
  std::string out = "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment written by linesurf\nelement vertex ";
  AppendUnsigned(out, mesh.vertices.size());
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  AppendUnsigned(out, faces.Count());
  out += small_faces ? "\nproperty list uchar uint vertex_indices\nend_header\n"
                     : "\nproperty list uint uint vertex_indices\nend_header\n";
  out.reserve(out.size() + mesh.vertices.size() * (ascii ? 60 : 24) + faces.indices.size() * 8);
  for (const Vec3& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      if (ascii) {
        if (k > 0) out.push_back(' ');
        AppendDouble(out, v[k]);
      } else {
        AppendLittleEndian(out, v[k]);
      }
    }
    if (ascii) out.push_back('\n');
  }
  for (std::size_t f = 0; f < faces.Count(); ++f) {
    const std::uint32_t n = faces.offsets[f + 1] - faces.offsets[f];
    if (ascii) {
      AppendUnsigned(out, n);
    } else if (small_faces) {
      AppendLittleEndian(out, static_cast<std::uint8_t>(n));
    } else {
      AppendLittleEndian(out, n);
    }
    for (std::uint32_t k = faces.offsets[f]; k < faces.offsets[f + 1]; ++k) {
      if (ascii) {
        out.push_back(' ');
        AppendUnsigned(out, faces.indices[k]);
      } else {
        AppendLittleEndian(out, faces.indices[k]);
      }
    }
    if (ascii) out.push_back('\n');
  }
  return out;
}

void AppendVertexLine(std::string& out, const char* prefix, const Vec3& v) {
  out += prefix;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out.push_back(' ');
    AppendDouble(out, v[k]);
  }
  out.push_back('\n');
}

std::string ObjText(const PolygonMesh& mesh, const FaceList& faces) {
  std::string out = "# written by linesurf\n";
  for (const Vec3& v : mesh.vertices) AppendVertexLine(out, "v ", v);
  for (std::size_t f = 0; f < faces.Count(); ++f) {
    out.push_back('f');
    for (std::uint32_t k = faces.offsets[f]; k < faces.offsets[f + 1]; ++k) {
      out.push_back(' ');
      AppendUnsigned(out, faces.indices[k] + 1ull);  // OBJ indices are 1-based
    }
    out.push_back('\n');
  }
  return out;
}

std::string OffText(const PolygonMesh& mesh, const FaceList& faces) {
  std::string out = "OFF\n";
  AppendUnsigned(out, mesh.vertices.size());
  out.push_back(' ');
  AppendUnsigned(out, faces.Count());
  out += " 0\n";
  for (const Vec3& v : mesh.vertices) AppendVertexLine(out, "", v);
  for (std::size_t f = 0; f < faces.Count(); ++f) {
    AppendUnsigned(out, faces.offsets[f + 1] - faces.offsets[f]);
    for (std::uint32_t k = faces.offsets[f]; k < faces.offsets[f + 1]; ++k) {
      out.push_back(' ');
      AppendUnsigned(out, faces.indices[k]);
    }
    out.push_back('\n');
  }
  return out;
}

}  // namespace

Status WriteMesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                 const MeshWriteOptions& options) noexcept {
  return CatchAll(kMeshWriteStage, [&] {
    const std::string file = path.string();
    const MeshFormat format = MeshFormatOf(path);
    LINESURF_THROW_IF(format == MeshFormat::kUnknown,
                      kInvalidInput,
                      kMeshWriteStage,
                      file << ": unknown mesh extension '" << path.extension().string()
                           << "' (expected .ply, .obj or .off)");
    const FaceList faces = CheckedFaces(mesh, options, file);
    std::string text;
    switch (format) {
      case MeshFormat::kPly:
        text = PlyText(mesh, faces, options.ascii);
        break;
      case MeshFormat::kObj:
        text = ObjText(mesh, faces);
        break;
      default:
        text = OffText(mesh, faces);
        break;
    }
    WriteFileAtomically(path, text, kMeshWriteStage);
  });
}

}  // namespace linesurf::io
