#pragma once
// Per-run context passed explicitly to every stage: cancellation, progress, logging, threads.
// No global state: several runs may go on at once in one process. LogSink, LogLevel and
// Progress are the public ones (linesurf/run_control.h).

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <sstream>
#include <string>

#include "linesurf/run_control.h"

namespace linesurf {

class RunContext {
 public:
  /// `num_threads` 0 = automatic, 1 = serial.
  int num_threads = 0;
  std::function<bool()> is_cancelled;
  std::function<void(const Progress&)> on_progress;
  LogSink* log = nullptr;

  /// True once the host asked to stop; cheap enough to call per chunk of work.
  [[nodiscard]] bool ShouldStop() const {
    if (cancelled_.load(std::memory_order_relaxed)) return true;
    if (is_cancelled && is_cancelled()) {
      cancelled_.store(true, std::memory_order_relaxed);
      return true;
    }
    return false;
  }
  /// Throws kCancelled when the host asked to stop.
  void ThrowIfCancelled(const std::string& stage) const;

  /// Reports progress, throttled to 10 Hz per stage and serialised; a throwing callback cancels.
  void ReportProgress(const std::string& stage, double fraction) const;

  void Log(LogLevel level, const std::string& stage, const std::string& message) const {
    if (log != nullptr) log->Write(level, stage, message);
  }

 private:
  mutable std::atomic<bool> cancelled_{false};
  mutable std::mutex progress_mutex_;
  mutable std::string last_stage_;
  mutable std::chrono::steady_clock::time_point last_report_{};
};

}  // namespace linesurf
