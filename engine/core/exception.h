#pragma once
// Internal error propagation: library code throws LinesurfException carrying an Error; stage
// entry points catch it (and every other exception) and return Expected<T>.

#include <exception>
#include <sstream>
#include <string>
#include <utility>

#include "linesurf/error.h"

namespace linesurf {

class LinesurfException : public std::exception {
 public:
  explicit LinesurfException(Error error) : error_(std::move(error)) {}
  const char* what() const noexcept override { return error_.message.c_str(); }
  [[nodiscard]] const Error& error() const noexcept { return error_; }

 private:
  Error error_;
};

[[noreturn]] inline void ThrowError(ErrorCode code, std::string stage, std::string message) {
  throw LinesurfException(Error{code, std::move(stage), std::move(message)});
}

/// The value of a stage result, or its error rethrown unchanged (the inverse of CatchAll below).
template <typename T>
T ValueOrThrow(Expected<T>&& result) {
  if (!result) throw LinesurfException(result.error());
  return std::move(result.value());
}

/// Runs `fn` and converts any exception (ours, bad_alloc, CGAL's, TBB-rethrown) into an Error.
template <typename Fn>
auto CatchAll(const std::string& stage, Fn&& fn) noexcept -> Expected<decltype(fn())> {
  try {
    if constexpr (std::is_void_v<decltype(fn())>) {
      fn();
      return {};
    } else {
      return fn();
    }
  } catch (const LinesurfException& e) {
    return e.error();
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::kResourceExhausted, stage, "out of memory"};
  } catch (const std::exception& e) {
    return Error{ErrorCode::kInternal, stage, e.what()};
  } catch (...) {
    return Error{ErrorCode::kInternal, stage, "unknown exception"};
  }
}

}  // namespace linesurf

/// Throws a LinesurfException with `code` when `cond` holds; `msg` may use stream syntax.
#define LINESURF_THROW_IF(cond, code, stage, msg)                                \
  do {                                                                           \
    if (cond) {                                                                  \
      std::ostringstream linesurf_msg_;                                          \
      linesurf_msg_ << msg;                                                      \
      ::linesurf::ThrowError(::linesurf::ErrorCode::code, stage, linesurf_msg_.str()); \
    }                                                                            \
  } while (false)

/// Invariant check that throws kInternal (never aborts, so tests can catch it).
#define LINESURF_ASSERT(cond)                                                              \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      ::linesurf::ThrowError(::linesurf::ErrorCode::kInternal, "assert",                   \
                             std::string(__FILE__) + ":" + std::to_string(__LINE__) + ": " \
                                 #cond);                                                   \
    }                                                                                      \
  } while (false)
