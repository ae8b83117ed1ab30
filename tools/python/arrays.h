#pragma once
// numpy arrays <-> the facade's plain types. Inputs are copied into facade vectors (a few MB at
// most, next to a reconstruction's cost) so that any dtype and memory layout numpy can convert
// is accepted; outputs are new numpy arrays owning their data.

#include "linesurf/linesurf.h"

#include <string_view>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace linesurf::python {

namespace py = pybind11;

/// (n, 2, 3) or (n, 6) float array (or None: empty) -> segments p1, p2.
std::vector<Segment> SegmentsFromArray(const py::object& array);
/// (m, 3) float array (or None) -> points.
std::vector<Vector3> PointsFromArray(const py::object& array, std::string_view name);
/// (k, 2) integer array (or None) -> observations (segment, viewpoint).
std::vector<Observation> ObservationsFromArray(const py::object& array);
/// (p, 2, 3) or (p, 6) float array (or None) -> planes (point, normal).
std::vector<Plane> PlanesFromArray(const py::object& array);
/// (q, 2) integer array (or None) -> memberships (segment, plane).
std::vector<Membership> MembershipsFromArray(const py::object& array);

/// (n, 2, 3) float64.
py::array_t<double> SegmentsToArray(const std::vector<Segment>& segments);
/// (n, 3) float64.
py::array_t<double> PointsToArray(const std::vector<Vector3>& points);
/// (k, 2) uint32.
py::array_t<std::uint32_t> ObservationsToArray(const std::vector<Observation>& observations);
/// (p, 2, 3) float64: [i, 0] point, [i, 1] unit normal.
py::array_t<double> PlanesToArray(const std::vector<Plane>& planes);
/// (q, 2) uint32.
py::array_t<std::uint32_t> MembershipsToArray(const std::vector<Membership>& memberships);
/// 1-D uint32.
py::array_t<std::uint32_t> IndicesToArray(const std::vector<std::uint32_t>& indices);
/// 1-D uint32 array -> indices; `name` for errors.
std::vector<std::uint32_t> IndicesFromArray(const py::object& array, std::string_view name);

}  // namespace linesurf::python
