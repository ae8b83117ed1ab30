#pragma once
/// @file error.h
/// @brief Error codes, the Error value and Expected<T>, the result type of every linesurf call.

#include <string>
#include <utility>
#include <variant>

namespace linesurf {
inline namespace v3 {

/// What went wrong, coarsely; hosts switch on it, people read Error::message.
enum class ErrorCode {
  kInvalidOptions,     ///< an option is out of its documented range
  kInvalidInput,       ///< the input is malformed or holds nothing usable
  kDegenerate,         ///< the input is valid but geometrically degenerate for the task
  kCancelled,          ///< the host asked to stop
  kSolverFailed,       ///< the optimisation did not reach an optimum
  kResourceExhausted,  ///< out of memory or over a size limit
  kInternal,           ///< a broken invariant: a bug in linesurf
};

/// Name of an error code, e.g. "invalid_input".
[[nodiscard]] inline const char* ErrorCodeName(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::kInvalidOptions:
      return "invalid_options";
    case ErrorCode::kInvalidInput:
      return "invalid_input";
    case ErrorCode::kDegenerate:
      return "degenerate";
    case ErrorCode::kCancelled:
      return "cancelled";
    case ErrorCode::kSolverFailed:
      return "solver_failed";
    case ErrorCode::kResourceExhausted:
      return "resource_exhausted";
    case ErrorCode::kInternal:
      return "internal";
  }
  return "unknown";
}

/// An error: its code, the stage that raised it (e.g. "read_reference_json") and a message that
/// names the offending file, line/index and field.
struct Error {
  ErrorCode code = ErrorCode::kInternal;
  std::string stage;
  std::string message;

  /// "stage: message" for printing.
  [[nodiscard]] std::string ToString() const {
    return stage.empty() ? message : stage + ": " + message;
  }
};

/// Holds either a T or an Error (mirrors C++23 std::expected).
template <typename T>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : storage_(std::in_place_index<0>, std::move(value)) {}      // NOLINT
  Expected(Error error) : storage_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

  [[nodiscard]] bool has_value() const noexcept { return storage_.index() == 0; }
  explicit operator bool() const noexcept { return has_value(); }
  T& value() & { return std::get<0>(storage_); }
  const T& value() const& { return std::get<0>(storage_); }
  T&& value() && { return std::get<0>(std::move(storage_)); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  [[nodiscard]] const Error& error() const { return std::get<1>(storage_); }

 private:
  std::variant<T, Error> storage_;
};

/// Expected<void>: success or an Error.
template <>
class [[nodiscard]] Expected<void> {
 public:
  Expected() = default;
  Expected(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT
  [[nodiscard]] bool has_value() const noexcept { return ok_; }
  explicit operator bool() const noexcept { return ok_; }
  [[nodiscard]] const Error& error() const { return error_; }

 private:
  Error error_;
  bool ok_ = true;
};

using Status = Expected<void>;

}  // namespace v3
}  // namespace linesurf
