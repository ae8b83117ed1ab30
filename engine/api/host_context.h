#pragma once
// The engine's RunContext for a host's RunControl: callbacks serialised (the facade promises
// they are never called concurrently) and exception-safe (a throwing callback cancels).

#include "linesurf/run_control.h"

#include "engine/core/run_context.h"

#include <mutex>

namespace linesurf::api {

class HostContext {
 public:
  /// `control` must outlive this object. `num_threads` as in the options (0 = automatic).
  HostContext(const RunControl& control, int num_threads);
  HostContext(const HostContext&) = delete;
  HostContext& operator=(const HostContext&) = delete;

  [[nodiscard]] const RunContext& Context() const { return ctx_; }

 private:
  const RunControl& control_;
  std::mutex mutex_;
  RunContext ctx_;
};

}  // namespace linesurf::api
