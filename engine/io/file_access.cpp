#include "engine/io/file_access.h"

#include <fstream>
#include <system_error>

#include "engine/core/exception.h"

namespace linesurf::io {

std::string ReadWholeFile(const std::filesystem::path& path, const std::string& stage) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  LINESURF_THROW_IF(!std::filesystem::exists(status), kInvalidInput, stage,
                    path.string() << ": no such file");
  LINESURF_THROW_IF(std::filesystem::is_directory(status), kInvalidInput, stage,
                    path.string() << ": is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  LINESURF_THROW_IF(!in, kInvalidInput, stage, path.string() << ": cannot be opened for reading");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  LINESURF_THROW_IF(size < 0, kInvalidInput, stage, path.string() << ": cannot be read");
  LINESURF_THROW_IF(size == 0, kInvalidInput, stage, path.string() << ": empty file");
  std::string content(static_cast<std::size_t>(size), '\0');
  in.seekg(0, std::ios::beg);
  in.read(content.data(), size);
  LINESURF_THROW_IF(in.gcount() != size, kInvalidInput, stage,
                    path.string() << ": read failed after " << in.gcount() << " of " << size
                                  << " bytes");
  return content;
}

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content,
                         const std::string& stage) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    LINESURF_THROW_IF(!out, kInvalidInput, stage,
                      path.string() << ": cannot be opened for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      ThrowError(ErrorCode::kInvalidInput, stage, path.string() + ": write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    ThrowError(ErrorCode::kInvalidInput, stage, path.string() + ": " + ec.message());
  }
}

}  // namespace linesurf::io
