#include "engine/api/scene_conversion.h"

#include "engine/core/exception.h"
#include "engine/core/world_frame.h"

#include <algorithm>
#include <string>

namespace linesurf::api {
namespace {

constexpr const char* kSceneConversionStage = "input_scene";

}  // namespace

Expected<Scene> ToEngineScene(const InputScene& input,
                              std::span<const std::array<double, 4>> residuals) {
  return CatchAll(kSceneConversionStage, [&]() -> Scene {
    const std::size_t num_segments = input.segments.size();
    const std::size_t num_viewpoints = input.viewpoints.size();
    const std::size_t num_planes = input.planes.size();
    LINESURF_THROW_IF(!residuals.empty() && residuals.size() != input.observations.size(),
                      kInvalidInput,
                      kSceneConversionStage,
                      residuals.size()
                          << " residuals for " << input.observations.size() << " observations");
    Scene scene;
    scene.segments.reserve(num_segments);
    for (const Segment& s : input.segments) {
      scene.segments.push_back(Segment3{ToVec3(s.p1), ToVec3(s.p2)});
    }
    scene.viewpoints.reserve(num_viewpoints);
    for (const Vector3& v : input.viewpoints) scene.viewpoints.push_back(ToVec3(v));

    // Observations grouped by segment, in input order within a segment.
    for (std::size_t k = 0; k < input.observations.size(); ++k) {
      const Observation& o = input.observations[k];
      LINESURF_THROW_IF(o.segment >= num_segments,
                        kInvalidInput,
                        kSceneConversionStage,
                        "observations[" << k << "].segment = " << o.segment << " is out of range ("
                                        << num_segments << " segments)");
      LINESURF_THROW_IF(o.viewpoint >= num_viewpoints,
                        kInvalidInput,
                        kSceneConversionStage,
                        "observations[" << k << "].viewpoint = " << o.viewpoint
                                        << " is out of range (" << num_viewpoints
                                        << " viewpoints)");
    }
    const auto by_segment = Csr<SegmentId, std::uint32_t>::FromPairs(
        num_segments,
        input.observations.size(),
        [&](std::size_t k) { return SegmentId(input.observations[k].segment); },
        [](std::size_t k) { return static_cast<std::uint32_t>(k); });
    scene.observations.Reserve(num_segments, by_segment.NumItems());
    std::vector<ViewpointId> row;
    for (std::size_t s = 0; s < num_segments; ++s) {
      row.clear();
      for (const std::uint32_t k : by_segment[SegmentId(s)]) {
        row.emplace_back(static_cast<std::size_t>(input.observations[k].viewpoint));
      }
      scene.observations.AddRow(row);
    }
    if (!residuals.empty()) {
      scene.residuals.reserve(by_segment.NumItems());
      for (const std::uint32_t k : by_segment.items()) scene.residuals.push_back(residuals[k]);
    }

    scene.planes.reserve(num_planes);
    for (const Plane& p : input.planes) {
      scene.planes.push_back(Plane3{ToVec3(p.point), ToVec3(p.normal)});
    }
    LINESURF_THROW_IF(num_planes == 0 && !input.memberships.empty(),
                      kInvalidInput,
                      kSceneConversionStage,
                      input.memberships.size() << " memberships but no planes");
    if (num_planes > 0) scene.memberships.resize(num_segments);
    for (std::size_t k = 0; k < input.memberships.size(); ++k) {
      const Membership& m = input.memberships[k];
      LINESURF_THROW_IF(m.segment >= num_segments,
                        kInvalidInput,
                        kSceneConversionStage,
                        "memberships[" << k << "].segment = " << m.segment << " is out of range ("
                                       << num_segments << " segments)");
      LINESURF_THROW_IF(m.plane >= num_planes,
                        kInvalidInput,
                        kSceneConversionStage,
                        "memberships[" << k << "].plane = " << m.plane << " is out of range ("
                                       << num_planes << " planes)");
      PlaneMembership& entry = scene.memberships[SegmentId(static_cast<std::size_t>(m.segment))];
      const PlaneId plane(static_cast<std::size_t>(m.plane));
      LINESURF_THROW_IF(!entry.Contains(plane) && !entry.Add(plane),
                        kInvalidInput,
                        kSceneConversionStage,
                        "memberships[" << k << "]: segment " << m.segment
                                       << " is already on two planes (at most two)");
    }
    return scene;
  });
}

SceneData ToSceneData(const Scene& scene) {
  const Rigid3& t = scene.world_from_local;
  SceneData data;
  data.segments.reserve(scene.NumSegments());
  for (const Segment3& s : scene.segments) {
    data.segments.push_back(
        Segment{ToVector3(ToWorldExact(s.p1, t)), ToVector3(ToWorldExact(s.p2, t))});
  }
  data.viewpoints.reserve(scene.viewpoints.size());
  for (const Vec3& v : scene.viewpoints) data.viewpoints.push_back(ToVector3(ToWorldExact(v, t)));
  data.observations.reserve(scene.observations.NumItems());
  for (std::size_t s = 0; s < scene.observations.NumRows(); ++s) {
    for (const ViewpointId v : scene.observations[SegmentId(s)]) {
      data.observations.push_back(
          Observation{static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(v.value())});
    }
  }
  data.planes = ToWorldPlanes(scene.planes, scene.world_from_local);
  for (std::size_t s = 0; s < scene.memberships.size(); ++s) {
    const PlaneMembership& m = scene.memberships[SegmentId(s)];
    for (std::uint8_t k = 0; k < m.count; ++k) {
      data.memberships.push_back(Membership{static_cast<std::uint32_t>(s),
                                            static_cast<std::uint32_t>(m.planes[k].value())});
    }
  }
  data.has_memberships = scene.HasMemberships();
  data.residuals = scene.residuals;
  data.extra_fields = scene.extra_fields;
  return data;
}

std::vector<Membership> ToMemberships(const IdVector<SegmentId, PlaneMembership>& memberships,
                                      const IdVector<SegmentId, SegmentId>& input_segment) {
  std::vector<Membership> out;
  for (std::size_t s = 0; s < memberships.size(); ++s) {
    const PlaneMembership& m = memberships[SegmentId(s)];
    const std::uint32_t segment = input_segment[SegmentId(s)].value();
    const std::size_t first = out.size();
    for (std::uint8_t k = 0; k < m.count; ++k) {
      out.push_back(Membership{segment, static_cast<std::uint32_t>(m.planes[k].value())});
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(first),
              out.end(),
              [](const Membership& a, const Membership& b) { return a.plane < b.plane; });
  }
  return out;
}

std::vector<Plane> ToWorldPlanes(const IdVector<PlaneId, Plane3>& planes,
                                 const Rigid3& world_from_local) {
  std::vector<Plane> out;
  out.reserve(planes.size());
  for (const Plane3& p : planes) {
    out.push_back(
        Plane{ToVector3(ToWorldExact(p.point, world_from_local)),
              ToVector3(world_from_local.Rotate(p.normal))});
  }
  return out;
}

}  // namespace linesurf::api
