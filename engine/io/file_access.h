#pragma once
// Whole-file reads and atomic whole-file writes with error messages that name the file.

#include <filesystem>
#include <string>
#include <string_view>

namespace linesurf::io {

/// Reads the whole file; throws kInvalidInput ("<file>: no such file", "... is a directory",
/// "... empty file", "... cannot be read") under `stage`.
std::string ReadWholeFile(const std::filesystem::path& path, const std::string& stage);

/// Writes `content` to "<path>.tmp" and renames it over `path`, so readers never see a partial
/// file; throws kInvalidInput when the file cannot be written (e.g. missing directory).
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content,
                         const std::string& stage);

}  // namespace linesurf::io
