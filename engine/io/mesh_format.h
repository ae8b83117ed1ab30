#pragma once
// Which mesh format a path names, from its extension.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace linesurf::io {

enum class MeshFormat { kUnknown, kPly, kObj, kOff };

/// The lower-case extension of `path` including the dot, e.g. ".ply".
inline std::string LowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

inline MeshFormat MeshFormatOf(const std::filesystem::path& path) {
  const std::string ext = LowerExtension(path);
  if (ext == ".ply") return MeshFormat::kPly;
  if (ext == ".obj") return MeshFormat::kObj;
  if (ext == ".off") return MeshFormat::kOff;
  return MeshFormat::kUnknown;
}

}  // namespace linesurf::io
