// Validate() of the facade's options: every value against its spec (option_schema.h), then the
// rules that tie options together.

#include "linesurf/option_schema.h"

#include "engine/api/options_conversion.h"
#include "engine/pipeline/evaluate_mesh.h"
#include "engine/pipeline/reconstruct.h"

namespace linesurf {
inline namespace v3 {
namespace {

/// The engine's rule, reported as an option error of the facade.
Status AsOptionError(Status s) {
  if (s) return s;
  return Error{ErrorCode::kInvalidOptions, "options", s.error().message};
}

}  // namespace

Status DetectOptions::Validate() const noexcept { return ValidateOptionValues(*this); }

Status EvaluationOptions::Validate() const noexcept {
  return pipeline::ValidateEvaluationOptions(*this);
}

Status ReconstructOptions::Validate() const noexcept {
  if (Status s = ValidateOptionValues(*this); !s) return s;
  if (Status s = AsOptionError(pipeline::ValidateOneBlockSize(
          engine == ComplexEngine::kMonolithic,
          block_size,
          {.block_size = "block_size", .detection_block_size = "detection.block_size"}));
      !s) {
    return s;
  }
  return AsOptionError(pipeline::ValidateMergeCoplanar(merge_coplanar, triangulate));
}

}  // namespace v3
}  // namespace linesurf
