#include "tools/python/arrays.h"

#include "tools/python/errors.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace linesurf::python {
namespace {

static_assert(sizeof(Vector3) == 3 * sizeof(double), "Vector3 must be three packed doubles");
static_assert(sizeof(Segment) == 6 * sizeof(double), "Segment must be six packed doubles");
static_assert(sizeof(Plane) == 6 * sizeof(double), "Plane must be six packed doubles");

using FloatArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IntArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

std::string ShapeString(const py::array& array) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    s += (d ? ", " : "") + std::to_string(array.shape(d));
  }
  return s + (array.ndim() == 1 ? ",)" : ")");
}

// True when `array` is (n, width), or (n, 2, 3) for width 6 (two points per row), or empty.
bool HasRowsOf(const py::array& array, py::ssize_t width) {
  if (array.size() == 0) return true;
  if (array.ndim() == 2) return array.shape(1) == width;
  return width == 6 && array.ndim() == 3 && array.shape(1) == 2 && array.shape(2) == 3;
}

std::string ExpectedShape(py::ssize_t width) {
  return width == 6 ? "(n, 2, 3) or (n, 6)" : "(n, " + std::to_string(width) + ")";
}

// Rows of `width` doubles (None: no rows), converted to float64 C order.
FloatArray FloatRows(const py::object& object, std::string_view name, py::ssize_t width) {
  if (object.is_none()) return FloatArray(std::vector<py::ssize_t>{0, width});
  FloatArray array = FloatArray::ensure(object);
  if (!array) throw py::type_error(std::string(name) + ": expected a numeric array");
  if (!HasRowsOf(array, width)) {
    throw py::value_error(std::string(name) + ": expected an array of shape " +
                          ExpectedShape(width) + ", got " + ShapeString(array));
  }
  return array;
}

// Rows of two non-negative 32-bit indices (None: no rows); `fields` names the two columns.
std::vector<std::array<std::uint32_t, 2>> IndexPairs(const py::object& object,
                                                     std::string_view name,
                                                     const char* const (&fields)[2]) {
  std::vector<std::array<std::uint32_t, 2>> pairs;
  if (object.is_none()) return pairs;
  py::array raw = py::array::ensure(object);
  if (!raw) throw py::type_error(std::string(name) + ": expected an integer array");
  if (raw.size() == 0) return pairs;
  if (const char kind = raw.dtype().kind(); kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + ": expected an integer array, got dtype " +
                         py::str(raw.dtype()).cast<std::string>());
  }
  if (!HasRowsOf(raw, 2)) {
    throw py::value_error(std::string(name) + ": expected an array of shape (n, 2), got " +
                          ShapeString(raw));
  }
  IntArray array = IntArray::ensure(raw);
  const std::int64_t* data = array.data();
  pairs.resize(static_cast<std::size_t>(array.shape(0)));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    for (std::size_t c = 0; c < 2; ++c) {
      const std::int64_t v = data[2 * i + c];
      if (v < 0 || v > std::numeric_limits<std::uint32_t>::max()) {
        RaiseInvalidInput(std::string(name) + "[" + std::to_string(i) + "]." + fields[c] + " = " +
                          std::to_string(v) + " is not a valid index");
      }
      pairs[i][c] = static_cast<std::uint32_t>(v);
    }
  }
  return pairs;
}

// Copies rows of doubles into trivially copyable facade values of the same layout.
template <typename T>
std::vector<T> CopyRows(const FloatArray& array) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<T> out(static_cast<std::size_t>(array.size()) * sizeof(double) / sizeof(T));
  if (!out.empty()) {
    std::memcpy(static_cast<void*>(out.data()), array.data(), out.size() * sizeof(T));
  }
  return out;
}

template <typename T>
py::array_t<double> ToFloatArray(const std::vector<T>& values, std::vector<py::ssize_t> row_shape) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(values.size())};
  shape.insert(shape.end(), row_shape.begin(), row_shape.end());
  py::array_t<double> array(shape);
  if (!values.empty()) std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(T));
  return array;
}

template <typename Pair>
py::array_t<std::uint32_t> PairsToArray(const std::vector<Pair>& pairs,
                                        std::uint32_t Pair::*first,
                                        std::uint32_t Pair::*second) {
  py::array_t<std::uint32_t> array(
      std::vector<py::ssize_t>{static_cast<py::ssize_t>(pairs.size()), 2});
  std::uint32_t* out = array.mutable_data();
  for (const Pair& p : pairs) {
    *out++ = p.*first;
    *out++ = p.*second;
  }
  return array;
}

constexpr const char* kObservationFields[2] = {"segment", "viewpoint"};
constexpr const char* kMembershipFields[2] = {"segment", "plane"};

}  // namespace

std::vector<Segment> SegmentsFromArray(const py::object& array) {
  return CopyRows<Segment>(FloatRows(array, "segments", 6));
}

std::vector<Vector3> PointsFromArray(const py::object& array, std::string_view name) {
  return CopyRows<Vector3>(FloatRows(array, name, 3));
}

std::vector<Plane> PlanesFromArray(const py::object& array) {
  return CopyRows<Plane>(FloatRows(array, "planes", 6));
}

std::vector<Observation> ObservationsFromArray(const py::object& array) {
  std::vector<Observation> out;
  for (const auto& [segment, viewpoint] : IndexPairs(array, "observations", kObservationFields)) {
    out.push_back(Observation{segment, viewpoint});
  }
  return out;
}

std::vector<Membership> MembershipsFromArray(const py::object& array) {
  std::vector<Membership> out;
  for (const auto& [segment, plane] : IndexPairs(array, "memberships", kMembershipFields)) {
    out.push_back(Membership{segment, plane});
  }
  return out;
}

std::vector<std::uint32_t> IndicesFromArray(const py::object& object, std::string_view name) {
  std::vector<std::uint32_t> out;
  py::array raw = py::array::ensure(object);
  if (!raw || raw.ndim() != 1 ||
      (raw.size() > 0 && raw.dtype().kind() != 'i' && raw.dtype().kind() != 'u')) {
    throw py::type_error(std::string(name) + ": expected a 1-D integer array");
  }
  IntArray array = IntArray::ensure(raw);
  for (py::ssize_t i = 0; i < array.size(); ++i) {
    const std::int64_t v = array.data()[i];
    if (v < 0 || v > std::numeric_limits<std::uint32_t>::max()) {
      RaiseInvalidInput(std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(v) +
                        " is not a valid index");
    }
    out.push_back(static_cast<std::uint32_t>(v));
  }
  return out;
}

py::array_t<double> SegmentsToArray(const std::vector<Segment>& segments) {
  return ToFloatArray(segments, {2, 3});
}

py::array_t<double> PointsToArray(const std::vector<Vector3>& points) {
  return ToFloatArray(points, {3});
}

py::array_t<double> PlanesToArray(const std::vector<Plane>& planes) {
  return ToFloatArray(planes, {2, 3});
}

py::array_t<std::uint32_t> ObservationsToArray(const std::vector<Observation>& observations) {
  return PairsToArray(observations, &Observation::segment, &Observation::viewpoint);
}

py::array_t<std::uint32_t> MembershipsToArray(const std::vector<Membership>& memberships) {
  return PairsToArray(memberships, &Membership::segment, &Membership::plane);
}

py::array_t<std::uint32_t> IndicesToArray(const std::vector<std::uint32_t>& indices) {
  py::array_t<std::uint32_t> array(static_cast<py::ssize_t>(indices.size()));
  if (!indices.empty()) {
    std::memcpy(array.mutable_data(), indices.data(), indices.size() * sizeof(std::uint32_t));
  }
  return array;
}

}  // namespace linesurf::python
