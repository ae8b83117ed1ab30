#include "tests/support/t_junctions.h"

#include <Eigen/Core>

namespace linesurf::testing {

std::size_t CountTJunctions(const PolygonMesh& mesh) {
  constexpr double kTolerance = 1e-9;
  std::size_t count = 0;
  for (std::size_t f = 0; f < mesh.NumFaces(); ++f) {
    const auto face = mesh.Face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vec3& a = mesh.vertices[face[k]];
      const Vec3& b = mesh.vertices[face[(k + 1) % face.size()]];
      const double length = (b - a).norm();
      const Vec3 lo = a.cwiseMin(b).array() - kTolerance * length;
      const Vec3 hi = a.cwiseMax(b).array() + kTolerance * length;
      for (const Vec3& p : mesh.vertices) {
        if (p == a || p == b || (p.array() < lo.array()).any() || (p.array() > hi.array()).any()) {
          continue;
        }
        const double t = (p - a).dot(b - a) / (length * length);
        if (t > kTolerance && t < 1 - kTolerance &&
            (a + t * (b - a) - p).norm() < kTolerance * length) {
          ++count;
        }
      }
    }
  }
  return count;
}

}  // namespace linesurf::testing
