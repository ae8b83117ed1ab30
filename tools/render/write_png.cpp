#include "tools/render/write_png.h"

#include <png.h>

#include <cstdio>
#include <string>
#include <vector>

#include "engine/core/exception.h"

namespace linesurf {
namespace {

constexpr const char* kWritePngStage = "write_png";

/// Only plain data lives in this frame: libpng reports errors by longjmp back to setjmp.
bool WriteRows(std::FILE* file, const Image& image, png_bytep* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_compression_level(png, 9);
  png_set_filter(png, 0, PNG_ALL_FILTERS);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

Status WritePng(const Image& image, const std::filesystem::path& path) noexcept {
  return CatchAll(kWritePngStage, [&] {
    LINESURF_THROW_IF(image.width <= 0 || image.height <= 0 ||
                          image.rgb.size() != 3 * static_cast<std::size_t>(image.width) *
                                                  static_cast<std::size_t>(image.height),
                      kInvalidInput,
                      kWritePngStage,
                      "image buffer does not match its size");
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y) {
      // libpng's row pointers are non-const but it only reads them when writing.
      rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(
          image.rgb.data() + 3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width));
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    LINESURF_THROW_IF(
        file == nullptr, kInvalidInput, kWritePngStage, "cannot open " << path << " for writing");
    const bool written = WriteRows(file, image, rows.data());
    const bool closed = std::fclose(file) == 0;
    LINESURF_THROW_IF(
        !written || !closed, kInvalidInput, kWritePngStage, "failed to write " << path);
  });
}

}  // namespace linesurf
