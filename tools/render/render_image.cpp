#include "tools/render/render_image.h"

#include "engine/core/exception.h"
#include "engine/core/face_triangulation.h"
#include "engine/core/geometry.h"
#include "engine/core/polygon_mesh.h"
#include "engine/core/public_mesh.h"
#include "engine/core/public_vector.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace linesurf {
namespace {

constexpr const char* kRenderImageStage = "render_image";
constexpr double kPi = 3.14159265358979323846;
/// Points closer to the eye than this share of the view distance are clipped.
constexpr double kNearFraction = 1e-3;
/// Share of points ignored at each end of every axis when framing segments (outliers).
constexpr double kFramingQuantile = 0.005;
/// Framing margin around the bounding sphere.
constexpr double kFramingMargin = 1.08;
/// Relative depth slack letting facet outlines win over their own faces.
constexpr double kOutlineDepthSlack = 2e-3;
/// How much far segments fade towards the background (depth cue).
constexpr double kDepthFade = 0.45;
/// Depth range below which all segments count as equally far (avoids dividing by zero).
constexpr double kMinDepthSpan = 1e-12;
constexpr std::array<std::uint8_t, 3> kColourFront{222, 214, 196};
constexpr std::array<std::uint8_t, 3> kColourBackFace{150, 170, 200};
constexpr std::array<std::uint8_t, 3> kColourOutline{45, 45, 45};
constexpr std::array<std::uint8_t, 3> kColourSeparator{200, 200, 200};

using Colour = std::array<double, 3>;

/// The segments to draw, in world coordinates, with their number of planes (0, 1 or 2).
struct WorldLines {
  std::vector<Segment3> segments;
  std::vector<int> plane_counts;
};

WorldLines ToWorldLines(const SceneData& scene) {
  WorldLines lines;
  lines.segments.reserve(scene.segments.size());
  for (const Segment& s : scene.segments) lines.segments.push_back({ToVec3(s.p1), ToVec3(s.p2)});
  lines.plane_counts.assign(scene.segments.size(), 0);
  if (!scene.has_memberships) return lines;
  for (std::size_t i = 0; i < scene.memberships.size(); ++i) {
    const std::uint32_t s = scene.memberships[i].segment;
    LINESURF_THROW_IF(s >= scene.segments.size(), kInvalidInput, kRenderImageStage,
                      "membership " << i << " refers to segment " << s << " of "
                                    << scene.segments.size());
    ++lines.plane_counts[s];
  }
  return lines;
}

/// The camera of RenderOptions in engine vectors.
struct ViewCamera {
  Vec3 eye;
  Vec3 target;
};

Colour ToColour(const std::array<std::uint8_t, 3>& c) {
  return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
}

/// Pinhole projection of world points into a panel of the supersampled canvas.
class Projector {
 public:
  Projector(const ViewCamera& camera, double fov_degrees, int width, int height)
      : eye_(camera.eye), width_(width), height_(height) {
    forward_ = (camera.target - camera.eye).normalized();
    Vec3 up = Vec3::UnitZ();
    if (std::abs(forward_.dot(up)) > 0.999) up = Vec3::UnitY();
    right_ = forward_.cross(up).normalized();
    up_ = right_.cross(forward_);
    focal_ = 0.5 * height / std::tan(0.5 * fov_degrees * kPi / 180.0);
    near_ = kNearFraction * (camera.target - camera.eye).norm();
  }
  /// Camera-space depth along the view direction.
  [[nodiscard]] double Depth(const Vec3& p) const { return (p - eye_).dot(forward_); }
  [[nodiscard]] double Near() const { return near_; }
  /// Screen position (pixels, y down) and inverse depth of a point in front of the near plane.
  [[nodiscard]] Vec3 Project(const Vec3& p) const {
    const Vec3 d = p - eye_;
    const double z = d.dot(forward_);
    return {0.5 * width_ + focal_ * d.dot(right_) / z, 0.5 * height_ - focal_ * d.dot(up_) / z,
            1.0 / z};
  }
  [[nodiscard]] const Vec3& Forward() const { return forward_; }
  [[nodiscard]] const Vec3& Up() const { return up_; }
  [[nodiscard]] const Vec3& Right() const { return right_; }
  [[nodiscard]] const Vec3& Eye() const { return eye_; }

 private:
  Vec3 eye_, forward_, right_, up_;
  double focal_ = 1.0;
  double near_ = 0.0;
  int width_, height_;
};

/// A supersampled panel: colour and inverse-depth buffers.
class Canvas {
 public:
  Canvas(int width, int height)
      : width_(width),
        height_(height),
        colour_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                ToColour(kColourBackground)),
        inverse_depth_(colour_.size(), 0.0) {}
  [[nodiscard]] int Width() const { return width_; }
  [[nodiscard]] int Height() const { return height_; }
  [[nodiscard]] bool Inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }
  Colour& At(int x, int y) { return colour_[Index(x, y)]; }
  double& DepthAt(int x, int y) { return inverse_depth_[Index(x, y)]; }
  [[nodiscard]] const Colour& At(int x, int y) const { return colour_[Index(x, y)]; }

 private:
  int width_, height_;
  std::vector<Colour> colour_;
  std::vector<double> inverse_depth_;
};

/// Clips a segment to the half-space in front of the near plane; false when nothing is left.
bool ClipToNear(const Projector& proj, Vec3& a, Vec3& b) {
  const double za = proj.Depth(a) - proj.Near();
  const double zb = proj.Depth(b) - proj.Near();
  if (za <= 0 && zb <= 0) return false;
  if (za < 0) a = a + (b - a) * (za / (za - zb));
  if (zb < 0) b = b + (a - b) * (zb / (zb - za));
  return true;
}

/// Draws a thick segment by stamping discs along it. With `depth_test`, a pixel is drawn only
/// when the segment is not behind what the buffer holds (with a slack so outlines of visible
/// faces show).
void DrawSegment(Canvas& canvas, const Projector& proj, Vec3 a, Vec3 b, double width,
                 const Colour& colour, bool depth_test) {
  if (!ClipToNear(proj, a, b)) return;
  const Vec3 pa = proj.Project(a);
  const Vec3 pb = proj.Project(b);
  const double length = std::hypot(pb.x() - pa.x(), pb.y() - pa.y());
  if (!std::isfinite(length)) return;
  const double radius = 0.5 * width;
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 2.0)));
  const int reach = static_cast<int>(std::ceil(radius));
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const double cx = pa.x() + t * (pb.x() - pa.x());
    const double cy = pa.y() + t * (pb.y() - pa.y());
    const double inv_z = pa.z() + t * (pb.z() - pa.z());  // 1/z is affine along screen lines
    const int ix = static_cast<int>(std::floor(cx));
    const int iy = static_cast<int>(std::floor(cy));
    for (int y = iy - reach; y <= iy + reach; ++y) {
      for (int x = ix - reach; x <= ix + reach; ++x) {
        if (!canvas.Inside(x, y)) continue;
        const double dx = x + 0.5 - cx;
        const double dy = y + 0.5 - cy;
        if (dx * dx + dy * dy > radius * radius) continue;
        if (depth_test && inv_z < canvas.DepthAt(x, y) * (1.0 - kOutlineDepthSlack)) continue;
        canvas.At(x, y) = colour;
      }
    }
  }
}

/// Fills a triangle (screen x, y, inverse depth) with the z-buffer.
void FillTriangle(Canvas& canvas, const Vec3& a, const Vec3& b, const Vec3& c, const Colour& colour) {
  const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  if (area == 0.0 || !std::isfinite(area)) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
  const int x1 = std::min(canvas.Width() - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
  const int y1 = std::min(canvas.Height() - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      const double py = y + 0.5;
      const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
      const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
      const double wc = 1.0 - wa - wb;
      if (wa < 0 || wb < 0 || wc < 0) continue;
      const double inv_z = wa * a.z() + wb * b.z() + wc * c.z();
      if (inv_z <= canvas.DepthAt(x, y)) continue;
      canvas.DepthAt(x, y) = inv_z;
      canvas.At(x, y) = colour;
    }
  }
}

void DrawMesh(Canvas& canvas, const Projector& proj, const PolygonMesh& mesh, int supersample) {
  const Vec3 light = (-proj.Forward() + 0.5 * proj.Up() - 0.3 * proj.Right()).normalized();
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    if (face.size() < 3) continue;
    Vec3 normal = Vec3::Zero();  // Newell's method: robust for any planar polygon
    Vec3 centroid = Vec3::Zero();
    bool in_front = true;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vec3& p = mesh.vertices[face[k]];
      const Vec3& q = mesh.vertices[face[(k + 1) % face.size()]];
      normal += p.cross(q);
      centroid += p;
      in_front = in_front && proj.Depth(p) > proj.Near();
    }
    if (!in_front || normal.squaredNorm() == 0.0) continue;
    normal.normalize();
    centroid /= static_cast<double>(face.size());
    const bool facing = normal.dot(proj.Eye() - centroid) >= 0.0;
    const Colour base = ToColour(facing ? kColourFront : kColourBackFace);
    const double shade = 0.4 + 0.6 * std::abs(normal.dot(light));
    const Colour colour{base[0] * shade, base[1] * shade, base[2] * shade};
    for (const auto& [a, b, c] : FaceTriangles(mesh.vertices, face)) {
      FillTriangle(canvas,
                   proj.Project(mesh.vertices[a]),
                   proj.Project(mesh.vertices[b]),
                   proj.Project(mesh.vertices[c]),
                   colour);
    }
  }
  const Colour outline = ToColour(kColourOutline);
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      DrawSegment(canvas, proj, mesh.vertices[face[k]], mesh.vertices[face[(k + 1) % face.size()]],
                  1.0 * supersample, outline, true);
    }
  }
}

void DrawLines(Canvas& canvas, const Projector& proj, const WorldLines& lines, double width) {
  const std::size_t n = lines.segments.size();
  std::vector<double> depth(n);
  for (std::size_t s = 0; s < n; ++s) depth[s] = proj.Depth(lines.segments[s].Midpoint());
  // Painter's order, far to near, ties by id.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  const auto [near_it, far_it] = std::minmax_element(depth.begin(), depth.end());
  const double near_depth = n > 0 ? *near_it : 0.0;
  const double span = n > 0 ? std::max(*far_it - near_depth, kMinDepthSpan) : 1.0;
  const Colour background = ToColour(kColourBackground);
  for (std::size_t s : order) {
    const int count = lines.plane_counts[s];
    const Colour base = ToColour(count == 0 ? kColourNoPlane : count == 1 ? kColourTextural : kColourStructural);
    const double fade = kDepthFade * std::clamp((depth[s] - near_depth) / span, 0.0, 1.0);
    Colour colour;
    for (int c = 0; c < 3; ++c) colour[c] = base[c] + fade * (background[c] - base[c]);
    DrawSegment(canvas, proj, lines.segments[s].p1, lines.segments[s].p2, width, colour, false);
  }
}

/// Robust box of the segment endpoints (quantiles per axis) joined with the mesh's full box.
Box3 FramingBox(const WorldLines* lines, const PolygonMesh* mesh) {
  Box3 box;
  if (lines != nullptr && !lines->segments.empty()) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      for (const Segment3& s : lines->segments) {
        values.push_back(s.p1[axis]);
        values.push_back(s.p2[axis]);
      }
      std::sort(values.begin(), values.end());
      const auto at = [&](double q) {
        return values[static_cast<std::size_t>(std::floor(q * static_cast<double>(values.size() - 1)))];
      };
      box.min[axis] = std::min(box.min[axis], at(kFramingQuantile));
      box.max[axis] = std::max(box.max[axis], at(1.0 - kFramingQuantile));
    }
  }
  if (mesh != nullptr) {
    for (const Vec3& v : mesh->vertices) box.Extend(v);
  }
  return box;
}

ViewCamera PresetCamera(const std::string& view, const Box3& box, double fov_degrees, double aspect) {
  Vec3 direction;  // from the target towards the eye
  if (view == "iso") direction = Vec3(1.0, -1.3, 0.9);
  else if (view == "iso-back") direction = Vec3(-1.0, 1.3, 0.9);
  else if (view == "front") direction = Vec3(0, -1, 0.15);
  else if (view == "back") direction = Vec3(0, 1, 0.15);
  else if (view == "left") direction = Vec3(-1, 0, 0.15);
  else if (view == "right") direction = Vec3(1, 0, 0.15);
  else direction = Vec3(0, 0, 1);  // "top" (Validate admits nothing else)
  const double radius = std::max(0.5 * box.Extent().norm(), 1e-9);
  const double half_fov = 0.5 * fov_degrees * kPi / 180.0;
  const double half_fov_x = std::atan(std::tan(half_fov) * aspect);
  const double distance = kFramingMargin * radius / std::sin(std::min(half_fov, half_fov_x));
  return {box.Center() + distance * direction.normalized(), box.Center()};
}

bool IsPresetView(const std::string& view) {
  for (const char* name : {"iso", "iso-back", "front", "back", "left", "right", "top"}) {
    if (view == name) return true;
  }
  return false;
}

Image Render(const WorldLines* lines, const PolygonMesh* mesh, const RenderOptions& options) {
  LINESURF_THROW_IF(lines == nullptr && mesh == nullptr,
                    kInvalidInput,
                    kRenderImageStage,
                    "nothing to render: give segments, a mesh or both");
  if (mesh != nullptr) {
    LINESURF_THROW_IF(
        mesh->face_offsets.empty() || mesh->face_offsets.back() != mesh->face_indices.size(),
        kInvalidInput,
        kRenderImageStage,
        "mesh face offsets do not cover the indices");
    for (std::uint32_t v : mesh->face_indices) {
      LINESURF_THROW_IF(v >= mesh->vertices.size(),
                        kInvalidInput,
                        kRenderImageStage,
                        "mesh face refers to vertex " << v << " of " << mesh->vertices.size());
    }
  }
  const int panels = (lines != nullptr && mesh != nullptr) ? 2 : 1;
  const int s = options.supersample;
  const int panel_width = options.width / panels;
  Box3 box = FramingBox(lines, mesh);
  if (box.IsEmpty()) box.Extend(Vec3::Zero());
  const double aspect = static_cast<double>(panel_width) / options.height;
  const ViewCamera camera =
      options.camera ? ViewCamera{ToVec3(options.camera->eye), ToVec3(options.camera->target)}
                     : PresetCamera(options.view, box, options.fov_degrees, aspect);
  LINESURF_THROW_IF((camera.target - camera.eye).norm() == 0.0,
                    kInvalidOptions,
                    kRenderImageStage,
                    "camera eye and target coincide");

  Image image;
  image.width = options.width;
  image.height = options.height;
  image.rgb.assign(3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), 255);
  for (int panel = 0; panel < panels; ++panel) {
    Canvas canvas(panel_width * s, options.height * s);
    const Projector proj(camera, options.fov_degrees, canvas.Width(), canvas.Height());
    const bool draw_lines = lines != nullptr && panel == 0;
    if (draw_lines) DrawLines(canvas, proj, *lines, options.line_width * s);
    else DrawMesh(canvas, proj, *mesh, s);
    // Box filter down to output pixels.
    const int x_offset = panel * panel_width;
    for (int y = 0; y < options.height; ++y) {
      for (int x = 0; x < panel_width; ++x) {
        Colour sum{0, 0, 0};
        for (int dy = 0; dy < s; ++dy) {
          for (int dx = 0; dx < s; ++dx) {
            const Colour& c = canvas.At(x * s + dx, y * s + dy);
            for (int k = 0; k < 3; ++k) sum[k] += c[k];
          }
        }
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                   static_cast<std::size_t>(x + x_offset));
        for (int k = 0; k < 3; ++k) {
          image.rgb[i + k] = static_cast<std::uint8_t>(std::clamp(std::lround(sum[k] / (s * s)), 0L, 255L));
        }
      }
    }
  }
  if (panels == 2) {  // a thin separator between the panels
    for (int y = 0; y < image.height; ++y) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                 static_cast<std::size_t>(panel_width));
      for (int k = 0; k < 3; ++k) image.rgb[i + k] = kColourSeparator[k];
    }
  }
  return image;
}

}  // namespace

Status RenderOptions::Validate() const {
  return CatchAll("render_options", [&] {
    LINESURF_THROW_IF(width < 16 || width > 8192 || height < 16 || height > 8192, kInvalidOptions,
                      "render_options", "image size " << width << "x" << height << " is outside [16, 8192]");
    LINESURF_THROW_IF(!camera && !IsPresetView(view), kInvalidOptions, "render_options",
                      "unknown view '" << view << "' (iso, iso-back, front, back, left, right, top)");
    LINESURF_THROW_IF(!(fov_degrees > 1.0 && fov_degrees < 120.0), kInvalidOptions, "render_options",
                      "fov_degrees must be in (1, 120)");
    LINESURF_THROW_IF(supersample < 1 || supersample > 4, kInvalidOptions, "render_options",
                      "supersample must be in [1, 4]");
    LINESURF_THROW_IF(!(line_width > 0.0 && line_width <= 16.0), kInvalidOptions, "render_options",
                      "line_width must be in (0, 16]");
    if (camera) {
      const Vec3 eye = ToVec3(camera->eye);
      const Vec3 target = ToVec3(camera->target);
      LINESURF_THROW_IF(!eye.allFinite() || !target.allFinite() || (eye - target).norm() == 0.0,
                        kInvalidOptions, "render_options", "camera eye and target must differ and be finite");
    }
  });
}

Expected<Image> RenderImage(const SceneData* lines, const Mesh* mesh,
                            const RenderOptions& options) noexcept {
  if (auto valid = options.Validate(); !valid) return valid.error();
  return CatchAll(kRenderImageStage, [&] {
    std::optional<WorldLines> world_lines;
    if (lines != nullptr) world_lines = ToWorldLines(*lines);
    std::optional<PolygonMesh> polygon_mesh;
    if (mesh != nullptr) polygon_mesh = ValueOrThrow(ToPolygonMesh(*mesh));
    return Render(world_lines ? &*world_lines : nullptr, polygon_mesh ? &*polygon_mesh : nullptr,
                  options);
  });
}

}  // namespace linesurf
