// Mesh readers: PLY (ascii, binary little/big endian), OBJ, OFF.

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <string_view>

#include "engine/core/coordinate_bound.h"
#include "engine/core/exception.h"
#include "engine/io/file_access.h"
#include "engine/io/mesh_format.h"
#include "engine/io/mesh_io.h"
#include "engine/io/text_lines.h"

namespace linesurf::io {
namespace {

constexpr const char* kMeshReadStage = "read_mesh";

#define LINESURF_MESH_FAIL_IF(cond, where, msg) \
  LINESURF_THROW_IF(cond, kInvalidInput, kMeshReadStage, file << ": " << where << ": " << msg)

Vec3 ParseVertex(const std::vector<std::string_view>& tokens, std::size_t first,
                 const std::string& file, const std::string& where) {
  LINESURF_MESH_FAIL_IF(tokens.size() < first + 3, where, "expected x y z");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    const std::string_view t = tokens[first + static_cast<std::size_t>(k)];
    LINESURF_MESH_FAIL_IF(!ParseDouble(t, v[k]) || !std::isfinite(v[k]), where,
                          "'" << t << "' is not a finite number");
  }
  return v;
}

/// Every vertex within the coordinate bound (what follows multiplies coordinates: beyond it
/// normals, areas and the exact predicates overflow), every face index in range.
void CheckMesh(const PolygonMesh& mesh, const std::string& file) {
  if (const auto violation = CoordinateBoundViolation(mesh)) {
    ThrowError(ErrorCode::kInvalidInput, kMeshReadStage, file + ": " + *violation);
  }
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    for (const std::uint32_t i : mesh.Face(f)) {
      LINESURF_THROW_IF(i >= mesh.vertices.size(),
                        kInvalidInput,
                        kMeshReadStage,
                        file << ": face " << f << ": vertex index " << i << " out of range ("
                             << mesh.vertices.size() << " vertices)");
    }
  }
}

// ---------------------------------------------------------------- OBJ

PolygonMesh ReadObj(std::string_view text, const std::string& file) {
  PolygonMesh mesh;
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  std::vector<std::uint32_t> face;
  while (reader.Next(tokens)) {
    if (tokens.empty() || tokens[0] == "#" || tokens[0].front() == '#') continue;
    const std::string where = "line " + std::to_string(reader.line_number());
    if (tokens[0] == "v") {
      mesh.vertices.push_back(ParseVertex(tokens, 1, file, where));
    } else if (tokens[0] == "f") {
      LINESURF_MESH_FAIL_IF(tokens.size() < 4, where, "a face needs at least 3 vertices");
      face.clear();
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view ref = tokens[k].substr(0, tokens[k].find('/'));  // a, a/b, a/b/c, a//c
        long long index = 0;
        LINESURF_MESH_FAIL_IF(!ParseInt(ref, index) || index == 0, where,
                              "'" << tokens[k] << "' is not a vertex reference");
        const long long n = static_cast<long long>(mesh.vertices.size());
        const long long zero_based = index > 0 ? index - 1 : n + index;  // negative: relative
        LINESURF_MESH_FAIL_IF(zero_based < 0 || zero_based >= n, where,
                              "vertex " << index << " out of range (" << n << " vertices so far)");
        face.push_back(static_cast<std::uint32_t>(zero_based));
      }
      mesh.AddFace(face);
    }
    // vt, vn, l, g, o, s, usemtl, mtllib, ...: not part of the polygon mesh, ignored
  }
  return mesh;
}

// ---------------------------------------------------------------- OFF

PolygonMesh ReadOff(std::string_view text, const std::string& file) {
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  // Next non-blank, non-comment line; false at the end.
  auto next = [&] {
    while (reader.Next(tokens)) {
      if (!tokens.empty() && tokens[0].front() != '#') return true;
    }
    return false;
  };
  LINESURF_THROW_IF(!next() || tokens[0].substr(0, 3) != "OFF",
                    kInvalidInput,
                    kMeshReadStage,
                    file << ": line 1: expected the OFF header");
  if (tokens.size() == 1) {  // counts on their own line (else on the header line)
    LINESURF_THROW_IF(
        !next(), kInvalidInput, kMeshReadStage, file << ": missing vertex/face counts");
  } else {
    tokens.erase(tokens.begin());
  }
  long long num_vertices = 0, num_faces = 0;
  std::string where = "line " + std::to_string(reader.line_number());
  LINESURF_MESH_FAIL_IF(tokens.size() < 2 || !ParseInt(tokens[0], num_vertices) ||
                            !ParseInt(tokens[1], num_faces) || num_vertices < 0 || num_faces < 0,
                        where, "expected 'vertices faces [edges]' counts");
  PolygonMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(std::min(num_vertices, 1LL << 26)));
  for (long long v = 0; v < num_vertices; ++v) {
    LINESURF_THROW_IF(!next(),
                      kInvalidInput,
                      kMeshReadStage,
                      file << ": vertex " << v << ": unexpected end of file (" << num_vertices
                           << " vertices announced)");
    mesh.vertices.push_back(
        ParseVertex(tokens, 0, file, "line " + std::to_string(reader.line_number())));
  }
  std::vector<std::uint32_t> face;
  for (long long f = 0; f < num_faces; ++f) {
    LINESURF_THROW_IF(
        !next(),
        kInvalidInput,
        kMeshReadStage,
        file << ": face " << f << ": unexpected end of file (" << num_faces << " faces announced)");
    where = "line " + std::to_string(reader.line_number());
    long long n = 0;
    LINESURF_MESH_FAIL_IF(!ParseInt(tokens[0], n) || n < 3 ||
                              tokens.size() < static_cast<std::size_t>(n) + 1,
                          where, "expected a vertex count >= 3 followed by that many indices");
    face.clear();
    for (long long k = 1; k <= n; ++k) {
      long long index = 0;
      LINESURF_MESH_FAIL_IF(!ParseInt(tokens[static_cast<std::size_t>(k)], index) || index < 0 ||
                                index >= num_vertices,
                            where, "vertex index '" << tokens[static_cast<std::size_t>(k)]
                                                    << "' out of range (" << num_vertices
                                                    << " vertices)");
      face.push_back(static_cast<std::uint32_t>(index));
    }
    mesh.AddFace(face);
  }
  return mesh;
}

// ---------------------------------------------------------------- PLY

enum class PlyType { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

bool ParsePlyType(std::string_view name, PlyType& type) {
  struct Entry {
    const char* a;
    const char* b;
    PlyType t;
  };
  static constexpr Entry kTypes[] = {
      {"char", "int8", PlyType::kInt8},      {"uchar", "uint8", PlyType::kUInt8},
      {"short", "int16", PlyType::kInt16},   {"ushort", "uint16", PlyType::kUInt16},
      {"int", "int32", PlyType::kInt32},     {"uint", "uint32", PlyType::kUInt32},
      {"float", "float32", PlyType::kFloat32}, {"double", "float64", PlyType::kFloat64}};
  for (const Entry& e : kTypes) {
    if (name == e.a || name == e.b) {
      type = e.t;
      return true;
    }
  }
  return false;
}

std::size_t PlyTypeSize(PlyType t) {
  switch (t) {
    case PlyType::kInt8:
    case PlyType::kUInt8: return 1;
    case PlyType::kInt16:
    case PlyType::kUInt16: return 2;
    case PlyType::kInt32:
    case PlyType::kUInt32:
    case PlyType::kFloat32: return 4;
    case PlyType::kFloat64: return 8;
  }
  return 0;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;
  bool is_list = false;
  PlyType count_type = PlyType::kUInt8;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

/// Reads binary values of any PLY type from a byte range, in file byte order.
class BinaryCursor {
 public:
  BinaryCursor(std::string_view data, bool big_endian) : data_(data), big_endian_(big_endian) {}

  /// Reads one value as double; false when the data ends first.
  bool Read(PlyType type, double& value) {
    const std::size_t size = PlyTypeSize(type);
    if (pos_ + size > data_.size()) return false;
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + pos_, size);
    pos_ += size;
    if (big_endian_ != (std::endian::native == std::endian::big)) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
    }
    switch (type) {
      case PlyType::kInt8: value = static_cast<std::int8_t>(bytes[0]); break;
      case PlyType::kUInt8: value = bytes[0]; break;
      case PlyType::kInt16: value = Load<std::int16_t>(bytes); break;
      case PlyType::kUInt16: value = Load<std::uint16_t>(bytes); break;
      case PlyType::kInt32: value = Load<std::int32_t>(bytes); break;
      case PlyType::kUInt32: value = Load<std::uint32_t>(bytes); break;
      case PlyType::kFloat32: value = Load<float>(bytes); break;
      case PlyType::kFloat64: value = Load<double>(bytes); break;
    }
    return true;
  }

 private:
  template <typename T>
  static double Load(const unsigned char* bytes) {
    T v;
    std::memcpy(&v, bytes, sizeof(T));
    return static_cast<double>(v);
  }
  std::string_view data_;
  bool big_endian_;
  std::size_t pos_ = 0;
};

/// Source of PLY values: ASCII (one element item per line) or binary.
class PlyValues {
 public:
  PlyValues(std::string_view body, bool ascii, bool big_endian, std::size_t first_line)
      : ascii_(ascii), lines_(body), binary_(body, big_endian), first_line_(first_line) {}

  /// Starts the next element item; `where` names it for errors.
  void BeginItem(const std::string& file, const std::string& where) {
    if (!ascii_) return;
    LINESURF_THROW_IF(!lines_.Next(tokens_),
                      kInvalidInput,
                      kMeshReadStage,
                      file << ": " << where << ": unexpected end of file");
    next_ = 0;
    where_ = where + " (line " + std::to_string(first_line_ + lines_.line_number()) + ")";
  }
  void Read(PlyType type, double& value, const std::string& file, const std::string& where) {
    if (ascii_) {
      LINESURF_THROW_IF(next_ >= tokens_.size(),
                        kInvalidInput,
                        kMeshReadStage,
                        file << ": " << where_ << ": too few values on the line");
      const std::string_view t = tokens_[next_++];
      LINESURF_THROW_IF(!ParseDouble(t, value),
                        kInvalidInput,
                        kMeshReadStage,
                        file << ": " << where_ << ": '" << t << "' is not a number");
      return;
    }
    LINESURF_THROW_IF(!binary_.Read(type, value),
                      kInvalidInput,
                      kMeshReadStage,
                      file << ": " << where << ": truncated binary data");
  }

 private:
  bool ascii_;
  LineReader lines_;
  BinaryCursor binary_;
  std::size_t first_line_;
  std::vector<std::string_view> tokens_;
  std::size_t next_ = 0;
  std::string where_;
};

/// A PLY header: the format, the elements, and where the body starts.
struct PlyHeader {
  bool ascii = false;
  bool big_endian = false;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  ///< of the first byte after end_header
  std::size_t body_line = 0;    ///< line number of end_header
};

/// One `property` declaration (scalar or list); fails on an unsupported one.
PlyProperty ParsePlyProperty(const std::vector<std::string_view>& tokens,
                             const std::string& file,
                             const std::string& where) {
  PlyProperty prop;
  bool ok = false;
  if (tokens.size() == 5 && tokens[1] == "list") {
    prop.is_list = true;
    ok = ParsePlyType(tokens[2], prop.count_type) && ParsePlyType(tokens[3], prop.type);
    prop.name = tokens[4];
  } else if (tokens.size() == 3) {
    ok = ParsePlyType(tokens[1], prop.type);
    prop.name = tokens[2];
  }
  LINESURF_MESH_FAIL_IF(!ok, where, "unsupported property declaration");
  return prop;
}

PlyHeader ReadPlyHeader(std::string_view text, const std::string& file) {
  LineReader header(text);
  std::vector<std::string_view> tokens;
  LINESURF_THROW_IF(!header.Next(tokens) || tokens.size() != 1 || tokens[0] != "ply",
                    kInvalidInput,
                    kMeshReadStage,
                    file << ": line 1: expected 'ply'");
  PlyHeader result;
  bool have_format = false, have_end = false;
  while (header.Next(tokens)) {
    const std::string where = "line " + std::to_string(header.line_number());
    if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
    if (tokens[0] == "end_header") {
      have_end = true;
      break;
    }
    if (tokens[0] == "format") {
      LINESURF_MESH_FAIL_IF(tokens.size() < 2, where, "format without a name");
      result.ascii = tokens[1] == "ascii";
      result.big_endian = tokens[1] == "binary_big_endian";
      LINESURF_MESH_FAIL_IF(!result.ascii && !result.big_endian &&
                                tokens[1] != "binary_little_endian",
                            where,
                            "unknown format '" << tokens[1] << "'");
      have_format = true;
    } else if (tokens[0] == "element") {
      long long count = 0;
      LINESURF_MESH_FAIL_IF(tokens.size() != 3 || !ParseInt(tokens[2], count) || count < 0, where,
                            "expected 'element <name> <count>'");
      result.elements.push_back(
          PlyElement{std::string(tokens[1]), static_cast<std::size_t>(count), {}});
    } else if (tokens[0] == "property") {
      LINESURF_MESH_FAIL_IF(result.elements.empty(), where, "property before any element");
      result.elements.back().properties.push_back(ParsePlyProperty(tokens, file, where));
    } else {
      LINESURF_MESH_FAIL_IF(true, where, "unknown header keyword '" << tokens[0] << "'");
    }
  }
  LINESURF_THROW_IF(!have_format || !have_end,
                    kInvalidInput,
                    kMeshReadStage,
                    file << ": incomplete PLY header (no format or end_header)");
  result.body_offset = header.position() > text.size() ? text.size() : header.position();
  result.body_line = header.line_number();
  return result;
}

/// Which properties of an element the mesh reads: the x, y, z scalars and the vertex index list
/// (-1 where absent).
struct PlyLayout {
  std::array<int, 3> axis = {-1, -1, -1};
  int list_index = -1;
};

PlyLayout LayoutOf(const PlyElement& element) {
  PlyLayout layout;
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty& prop = element.properties[p];
    if (!prop.is_list && prop.name.size() == 1 && prop.name[0] >= 'x' && prop.name[0] <= 'z') {
      layout.axis[prop.name[0] - 'x'] = static_cast<int>(p);
    }
    if (prop.is_list && (prop.name == "vertex_indices" || prop.name == "vertex_index")) {
      layout.list_index = static_cast<int>(p);
    }
  }
  return layout;
}

/// Reads the items of `element` from `values`, adding vertices and faces to `mesh`; skips the
/// items of other elements.
void ReadPlyElement(const PlyElement& element,
                    const std::string& file,
                    PlyValues& values,
                    PolygonMesh& mesh) {
  const PlyLayout layout = LayoutOf(element);
  const bool is_vertex = element.name == "vertex";
  const bool is_face = element.name == "face";
  LINESURF_THROW_IF(
      is_vertex && (layout.axis[0] < 0 || layout.axis[1] < 0 || layout.axis[2] < 0),
      kInvalidInput,
      kMeshReadStage,
      file << ": element vertex lacks an x, y or z property");
  LINESURF_THROW_IF(is_face && layout.list_index < 0,
                    kInvalidInput,
                    kMeshReadStage,
                    file << ": element face lacks a vertex_indices list");
  // An element without properties has no bytes to read: its count, up to 2^63, would only
  // spin (found by fuzzing: `element vertey 99999990`).
  if (element.properties.empty()) return;
  std::vector<std::uint32_t> face;
  for (std::size_t i = 0; i < element.count; ++i) {
    const std::string where = element.name + " " + std::to_string(i);
    values.BeginItem(file, where);
    Vec3 v = Vec3::Zero();
    face.clear();
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& prop = element.properties[p];
      double value = 0.0;
      if (!prop.is_list) {
        values.Read(prop.type, value, file, where);
        for (int k = 0; k < 3; ++k) {
          if (is_vertex && layout.axis[k] == static_cast<int>(p)) v[k] = value;
        }
        continue;
      }
      values.Read(prop.count_type, value, file, where);
      LINESURF_MESH_FAIL_IF(!(value >= 0.0) || value > 1e9, where, "bad list length " << value);
      const auto n = static_cast<std::size_t>(value);
      const bool is_indices = is_face && layout.list_index == static_cast<int>(p);
      for (std::size_t k = 0; k < n; ++k) {
        values.Read(prop.type, value, file, where);
        if (is_indices) {
          LINESURF_MESH_FAIL_IF(!(value >= 0.0) || value > 4294967294.0, where,
                                "vertex index " << value << " out of range");
          face.push_back(static_cast<std::uint32_t>(value));
        }
      }
    }
    if (is_vertex) {
      LINESURF_MESH_FAIL_IF(!v.allFinite(), where, "non-finite coordinate");
      mesh.vertices.push_back(v);
    }
    if (is_face) {
      LINESURF_MESH_FAIL_IF(face.size() < 3, where,
                            "a face needs at least 3 vertices, got " << face.size());
      mesh.AddFace(face);
    }
  }
}

PolygonMesh ReadPly(std::string_view text, const std::string& file) {
  const PlyHeader header = ReadPlyHeader(text, file);
  PolygonMesh mesh;
  PlyValues values(text.substr(header.body_offset), header.ascii, header.big_endian,
                   header.body_line);
  for (const PlyElement& element : header.elements) ReadPlyElement(element, file, values, mesh);
  return mesh;
}

}  // namespace

Expected<PolygonMesh> ReadMesh(const std::filesystem::path& path) noexcept {
  return CatchAll(kMeshReadStage, [&]() -> PolygonMesh {
    const std::string file = path.string();
    const MeshFormat format = MeshFormatOf(path);
    LINESURF_THROW_IF(format == MeshFormat::kUnknown,
                      kInvalidInput,
                      kMeshReadStage,
                      file << ": unknown mesh extension '" << path.extension().string()
                           << "' (expected .ply, .obj or .off)");
    const std::string content = ReadWholeFile(path, kMeshReadStage);
    PolygonMesh mesh = format == MeshFormat::kPly   ? ReadPly(content, file)
                       : format == MeshFormat::kObj ? ReadObj(content, file)
                                                    : ReadOff(content, file);
    CheckMesh(mesh, file);
    return mesh;
  });
}

}  // namespace linesurf::io
