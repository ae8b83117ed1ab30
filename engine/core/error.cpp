#include "linesurf/error.h"

namespace linesurf {
inline namespace v1 {

const char* ErrorCodeName(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::kInvalidOptions: return "invalid_options";
    case ErrorCode::kInvalidInput: return "invalid_input";
    case ErrorCode::kDegenerate: return "degenerate";
    case ErrorCode::kCancelled: return "cancelled";
    case ErrorCode::kSolverFailed: return "solver_failed";
    case ErrorCode::kResourceExhausted: return "resource_exhausted";
    case ErrorCode::kInternal: return "internal";
  }
  return "unknown";
}

std::string Error::ToString() const {
  return stage.empty() ? message : stage + ": " + message;
}

}  // namespace v1
}  // namespace linesurf
