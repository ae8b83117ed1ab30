#include "engine/core/exception.h"
#include "engine/io/camera_centres.h"
#include "engine/io/file_access.h"
#include "engine/io/little_endian_cursor.h"
#include "engine/io/mesh_format.h"
#include "engine/io/text_lines.h"

#include <Eigen/Geometry>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace linesurf::io {
namespace {

constexpr const char* kColmapModelStage = "read_cameras";

/// One registered image: its ids, centre, and where it was read (for error messages).
struct ColmapImage {
  std::int64_t image_id = 0;
  std::int64_t camera_id = 0;
  Vec3 centre;
  std::string where;  ///< "<file>: line 5" or "<file>: image 3 (byte 120)"
};

/// Centre = -R(q)^T t with q normalised; throws naming `where` for a zero quaternion.
Vec3 CentreOf(const double q[4], const double t[3], const std::string& where) {
  const Eigen::Quaterniond quaternion(q[0], q[1], q[2], q[3]);
  LINESURF_THROW_IF(
      !(quaternion.norm() > 0.0), kInvalidInput, kColmapModelStage, where << ": zero quaternion");
  const Eigen::Matrix3d r = quaternion.normalized().toRotationMatrix();
  return -(r.transpose() * Vec3(t[0], t[1], t[2]));
}

/// The uint64 record count a COLMAP .bin file starts with.
std::uint64_t ReadRecordCount(LittleEndianCursor& cursor, const std::string& file,
                              const char* record) {
  std::uint64_t count = 0;
  LINESURF_THROW_IF(!cursor.Read(count),
                    kInvalidInput,
                    kColmapModelStage,
                    file << ": shorter than its 8-byte " << record << " count");
  return count;
}

/// images.txt: after `#` comments, two lines per image (the POINTS2D line may be empty, so lines
/// are taken in pairs, not by content).
std::vector<ColmapImage> ReadImagesText(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kColmapModelStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  std::vector<ColmapImage> images;
  bool in_header = true;
  while (reader.Next(tokens)) {
    if (in_header && (tokens.empty() || tokens[0].front() == '#')) continue;
    in_header = false;
    if (tokens.empty()) continue;  // trailing blank lines
    ColmapImage image;
    image.where = file + ": line " + std::to_string(reader.line_number());
    long long image_id = 0;
    long long camera_id = 0;
    double v[7];  // qw qx qy qz tx ty tz
    LINESURF_THROW_IF(tokens.size() < 10 || !ParseInt(tokens[0], image_id) ||
                          !ParseFiniteNumbers(tokens, 1, 7, v) || !ParseInt(tokens[8], camera_id),
                      kInvalidInput,
                      kColmapModelStage,
                      image.where << ": expected 'IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME'");
    image.image_id = image_id;
    image.camera_id = camera_id;
    image.centre = CentreOf(v, v + 4, image.where);
    images.push_back(std::move(image));
    reader.Next(tokens);  // the POINTS2D line of this image (possibly empty)
  }
  return images;
}

/// images.bin (little endian): uint64 count, then per image uint32 IMAGE_ID, 4 doubles q,
/// 3 doubles t, uint32 CAMERA_ID, the NUL-terminated name, uint64 point count and that many
/// 24-byte points (double x, double y, int64 POINT3D_ID), skipped.
std::vector<ColmapImage> ReadImagesBinary(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string data = ReadWholeFile(path, kColmapModelStage);
  LittleEndianCursor cursor(data);
  const std::uint64_t count = ReadRecordCount(cursor, file, "image");
  std::vector<ColmapImage> images;
  for (std::uint64_t i = 0; i < count; ++i) {
    ColmapImage image;
    image.where =
        file + ": image " + std::to_string(i) + " (byte " + std::to_string(cursor.offset()) + ")";
    std::uint32_t image_id = 0;
    std::uint32_t camera_id = 0;
    double q[4];
    double t[3];
    std::string name;
    std::uint64_t points = 0;
    bool ok = cursor.Read(image_id);
    for (double& v : q) ok = ok && cursor.Read(v);
    for (double& v : t) ok = ok && cursor.Read(v);
    ok = ok && cursor.Read(camera_id) && cursor.ReadCString(name) && cursor.Read(points);
    LINESURF_THROW_IF(
        !ok,
        kInvalidInput,
        kColmapModelStage,
        image.where << ": file ends inside the image record (" << count << " images announced)");
    LINESURF_THROW_IF(points > data.size() / 24 || !cursor.Skip(24 * points),
                      kInvalidInput,
                      kColmapModelStage,
                      image.where << ": file ends inside its " << points << " 2D points");
    for (const double v : q) {
      LINESURF_THROW_IF(!std::isfinite(v),
                        kInvalidInput,
                        kColmapModelStage,
                        image.where << ": non-finite quaternion");
    }
    for (const double v : t) {
      LINESURF_THROW_IF(!std::isfinite(v),
                        kInvalidInput,
                        kColmapModelStage,
                        image.where << ": non-finite translation");
    }
    image.image_id = image_id;
    image.camera_id = camera_id;
    image.centre = CentreOf(q, t, image.where);
    images.push_back(std::move(image));
  }
  LINESURF_THROW_IF(!cursor.AtEnd(),
                    kInvalidInput,
                    kColmapModelStage,
                    file << ": " << data.size() - cursor.offset() << " bytes after the " << count
                         << " announced images");
  return images;
}

/// cameras.txt: `CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]` per non-comment line; ids only.
std::set<std::int64_t> ReadCameraIdsText(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = ReadWholeFile(path, kColmapModelStage);
  LineReader reader(text);
  std::vector<std::string_view> tokens;
  std::set<std::int64_t> ids;
  while (reader.Next(tokens)) {
    if (tokens.empty() || tokens[0].front() == '#') continue;
    long long id = 0;
    LINESURF_THROW_IF(tokens.size() < 4 || !ParseInt(tokens[0], id),
                      kInvalidInput,
                      kColmapModelStage,
                      file << ": line " << reader.line_number()
                           << ": expected 'CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]'");
    ids.insert(id);
  }
  return ids;
}

/// Number of parameters of each COLMAP camera model id (colmap/src/colmap/sensor/models.h:
/// SIMPLE_PINHOLE 0 .. RAD_TAN_THIN_PRISM_FISHEYE 11).
constexpr std::uint64_t kModelParams[] = {3, 4, 4, 5, 8, 8, 12, 5, 4, 5, 12, 16};

/// cameras.bin (little endian): uint64 count, then per camera uint32 CAMERA_ID, int32 MODEL_ID,
/// uint64 WIDTH, uint64 HEIGHT and the model's parameters as doubles; ids only.
std::set<std::int64_t> ReadCameraIdsBinary(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string data = ReadWholeFile(path, kColmapModelStage);
  LittleEndianCursor cursor(data);
  const std::uint64_t count = ReadRecordCount(cursor, file, "camera");
  std::set<std::int64_t> ids;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::size_t at = cursor.offset();
    std::uint32_t id = 0;
    std::int32_t model = 0;
    std::uint64_t width = 0;
    std::uint64_t height = 0;
    const bool ok =
        cursor.Read(id) && cursor.Read(model) && cursor.Read(width) && cursor.Read(height);
    LINESURF_THROW_IF(
        !ok,
        kInvalidInput,
        kColmapModelStage,
        file << ": camera " << i << " (byte " << at << "): file ends inside the camera record");
    LINESURF_THROW_IF(
        model < 0 || model >= static_cast<std::int32_t>(std::size(kModelParams)),
        kInvalidInput,
        kColmapModelStage,
        file << ": camera " << i << " (byte " << at << "): unknown MODEL_ID " << model);
    LINESURF_THROW_IF(
        !cursor.Skip(8 * kModelParams[model]),
        kInvalidInput,
        kColmapModelStage,
        file << ": camera " << i << " (byte " << at << "): file ends inside its parameters");
    ids.insert(id);
  }
  return ids;
}

}  // namespace

CameraCentres ReadColmapCameraCentres(const std::filesystem::path& path) {
  std::filesystem::path images = path;
  if (std::filesystem::is_directory(path)) {
    images =
        std::filesystem::exists(path / "images.bin") ? path / "images.bin" : path / "images.txt";
  }
  const bool binary = LowerExtension(images) == ".bin";
  const std::vector<ColmapImage> list = binary ? ReadImagesBinary(images) : ReadImagesText(images);
  const std::filesystem::path cameras =
      images.parent_path() / (binary ? "cameras.bin" : "cameras.txt");
  if (std::filesystem::exists(cameras)) {
    const std::set<std::int64_t> ids =
        binary ? ReadCameraIdsBinary(cameras) : ReadCameraIdsText(cameras);
    for (const ColmapImage& image : list) {
      LINESURF_THROW_IF(
          !ids.count(image.camera_id),
          kInvalidInput,
          kColmapModelStage,
          image.where << ": CAMERA_ID " << image.camera_id << " is not in " << cameras.string());
    }
  }
  CameraCentres centres;
  for (const ColmapImage& image : list) {
    LINESURF_THROW_IF(!centres.emplace(image.image_id, image.centre).second,
                      kInvalidInput,
                      kColmapModelStage,
                      image.where << ": IMAGE_ID " << image.image_id << " repeated");
  }
  return centres;
}

}  // namespace linesurf::io
