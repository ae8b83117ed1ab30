#pragma once
// Writers of small structure-from-motion fixtures for reader and CLI tests: a scene's viewpoints
// as VisualSfM NVM or COLMAP (text and binary) cameras, its segments as Line3D++ clusters or
// LIMAP alltracks.txt tracks observed by those cameras. Rotations are half turns (and identity),
// so t = -R c and the reader's c = -R^T t are exact: centres read back bit for bit.

#include "engine/core/scene.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace linesurf::testing {

struct FixtureCamera {
  long long id = 0;  ///< NVM: the 0-based index; COLMAP: IMAGE_ID
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 centre = Vec3::Zero();
  [[nodiscard]] Vec3 Translation() const { return -(rotation.toRotationMatrix() * centre); }
};

/// One camera per viewpoint of `scene` (viewpoint v -> id first_id + v * step), cycling through
/// the identity and half turns about x, y and z.
inline std::vector<FixtureCamera> CamerasFor(const Scene& scene,
                                             long long first_id,
                                             long long step) {
  const Eigen::Quaterniond turns[] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  std::vector<FixtureCamera> cameras;
  for (std::size_t v = 0; v < scene.viewpoints.size(); ++v) {
    cameras.push_back({first_id + static_cast<long long>(v) * step,
                       turns[v % 4],
                       scene.viewpoints[ViewpointId(v)]});
  }
  return cameras;
}

/// %.17g: reads back to the same double.
inline std::string ExactText(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

inline void WriteFixture(const std::filesystem::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

/// NVM_V3 with the cameras in order (their ids must be 0, 1, 2, ...) and no points.
inline std::string NvmText(const std::vector<FixtureCamera>& cameras) {
  std::string text = "NVM_V3\n\n" + std::to_string(cameras.size()) + "\n";
  for (const FixtureCamera& c : cameras) {
    const Eigen::Quaterniond& q = c.rotation;
    text += "view" + std::to_string(c.id) + ".jpg 500 " + ExactText(q.w()) + " " +
            ExactText(q.x()) + " " + ExactText(q.y()) + " " + ExactText(q.z()) + " " +
            ExactText(c.centre.x()) + " " + ExactText(c.centre.y()) + " " +
            ExactText(c.centre.z()) + " 0 0\n";
  }
  return text + "\n0\n";
}

/// COLMAP cameras.txt with the one PINHOLE camera (CAMERA_ID 1) every image uses.
inline std::string ColmapCamerasText() {
  return "# Camera list with one line of data per camera:\n"
         "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n1 PINHOLE 640 480 500 500 320 240\n";
}

/// COLMAP images.txt; every other image has an empty POINTS2D line.
inline std::string ColmapImagesText(const std::vector<FixtureCamera>& cameras) {
  std::string text =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n";
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const FixtureCamera& c = cameras[k];
    const Vec3 t = c.Translation();
    text += std::to_string(c.id) + " " + ExactText(c.rotation.w()) + " " +
            ExactText(c.rotation.x()) + " " + ExactText(c.rotation.y()) + " " +
            ExactText(c.rotation.z()) + " " + ExactText(t.x()) + " " + ExactText(t.y()) + " " +
            ExactText(t.z()) + " 1 image" + std::to_string(c.id) + ".png\n";
    text += k % 2 ? "\n" : "12.5 30.25 -1 40 50 7\n";
  }
  return text;
}

template <typename T>
void AppendBinary(std::string& out, T value) {  // little-endian hosts only (x86, arm64)
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

/// COLMAP cameras.bin with the PINHOLE camera 1 (MODEL_ID 1, 4 parameters).
inline std::string ColmapCamerasBinary() {
  std::string out;
  AppendBinary<std::uint64_t>(out, 1);
  AppendBinary<std::uint32_t>(out, 1);
  AppendBinary<std::int32_t>(out, 1);
  AppendBinary<std::uint64_t>(out, 640);
  AppendBinary<std::uint64_t>(out, 480);
  for (const double p : {500.0, 500.0, 320.0, 240.0}) AppendBinary(out, p);
  return out;
}

/// COLMAP images.bin; image k has k % 3 2D points.
inline std::string ColmapImagesBinary(const std::vector<FixtureCamera>& cameras) {
  std::string out;
  AppendBinary<std::uint64_t>(out, cameras.size());
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const FixtureCamera& c = cameras[k];
    const Vec3 t = c.Translation();
    AppendBinary<std::uint32_t>(out, static_cast<std::uint32_t>(c.id));
    for (const double v : {c.rotation.w(), c.rotation.x(), c.rotation.y(), c.rotation.z()}) {
      AppendBinary(out, v);
    }
    for (int i = 0; i < 3; ++i) AppendBinary(out, t[i]);
    AppendBinary<std::uint32_t>(out, 1);
    out += "image" + std::to_string(c.id) + ".png";
    out += '\0';
    AppendBinary<std::uint64_t>(out, k % 3);
    for (std::size_t p = 0; p < k % 3; ++p) {
      AppendBinary(out, 10.5 * static_cast<double>(p));
      AppendBinary(out, 20.25);
      AppendBinary<std::int64_t>(out, -1);
    }
  }
  return out;
}

/// Line3D++: one cluster per segment, observed by the cameras of its viewpoints; residuals from
/// the scene when it has them, else 0.
inline std::string Line3dppText(const Scene& scene, const std::vector<FixtureCamera>& cameras) {
  std::string text;
  auto field = [&text](const std::string& value) {  // appended, not " " + value (GCC 12 -Wrestrict)
    text += ' ';
    text += value;
  };
  std::size_t item = 0;
  for (std::size_t s = 0; s < scene.segments.size(); ++s) {
    const Segment3& seg = scene.segments[SegmentId(s)];
    text += "1";
    for (const Vec3& p : {seg.p1, seg.p2}) {
      for (int k = 0; k < 3; ++k) field(ExactText(p[k]));
    }
    const auto views = scene.observations[SegmentId(s)];
    field(std::to_string(views.size()));
    for (std::size_t o = 0; o < views.size(); ++o, ++item) {
      field(std::to_string(cameras[views[o].index()].id));
      field(std::to_string(o));
      for (int k = 0; k < 4; ++k) {
        field(scene.residuals.empty() ? std::string("0") : ExactText(scene.residuals[item][k]));
      }
    }
    text += '\n';
  }
  return text;
}

/// LIMAP alltracks.txt: one track per segment, supported by one 2D line in each observing
/// camera (as limap.util.io.save_txt_linetracks writes it, trailing spaces included).
inline std::string LimapText(const Scene& scene, const std::vector<FixtureCamera>& cameras) {
  std::string text = std::to_string(scene.segments.size()) + "\n";
  for (std::size_t s = 0; s < scene.segments.size(); ++s) {
    const Segment3& seg = scene.segments[SegmentId(s)];
    const auto views = scene.observations[SegmentId(s)];
    std::vector<long long> distinct;
    for (const ViewpointId v : views) {
      if (std::find(distinct.begin(), distinct.end(), v.index()) == distinct.end()) {
        distinct.push_back(v.index());
      }
    }
    text += std::to_string(s) + " " + std::to_string(views.size()) + " " +
            std::to_string(distinct.size()) + "\n";
    for (const Vec3& p : {seg.p1, seg.p2}) {
      text += ExactText(p.x()) + " " + ExactText(p.y()) + " " + ExactText(p.z()) + "\n";
    }
    for (const ViewpointId v : views) text += std::to_string(cameras[v.index()].id) + " ";
    text += "\n";
    for (std::size_t o = 0; o < views.size(); ++o) text += std::to_string(3 * s + o) + " ";
    text += "\n";
  }
  return text;
}

}  // namespace linesurf::testing
