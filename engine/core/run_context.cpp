#include "engine/core/run_context.h"

#include "engine/core/exception.h"

namespace linesurf {

void RunContext::ThrowIfCancelled(const std::string& stage) const {
  if (ShouldStop()) ThrowError(ErrorCode::kCancelled, stage, "cancelled by the host");
}

void RunContext::ReportProgress(const std::string& stage, double fraction) const {
  if (!on_progress) return;
  constexpr auto kMinInterval = std::chrono::milliseconds(100);
  std::lock_guard<std::mutex> lock(progress_mutex_);
  const auto now = std::chrono::steady_clock::now();
  const bool is_edge = fraction <= 0.0 || fraction >= 1.0 || stage != last_stage_;
  if (!is_edge && now - last_report_ < kMinInterval) return;
  last_stage_ = stage;
  last_report_ = now;
  try {
    on_progress(Progress{stage, fraction});
  } catch (...) {
    cancelled_.store(true, std::memory_order_relaxed);
  }
}

}  // namespace linesurf
