#pragma once
/// @file run_control.h
/// @brief What a host hands to a run besides its input and options: progress and cancel
/// callbacks and a log sink. All optional; the library never prints.

#include "linesurf/export.h"

#include <functional>
#include <string>

namespace linesurf {
inline namespace v3 {

enum class LogLevel { kDebug, kInfo, kWarning, kError };

/// Host-provided log destination. Write may be called from worker threads, concurrently: it
/// must be thread-safe and must not throw.
class LINESURF_API LogSink {
 public:
  virtual ~LogSink() = default;
  virtual void Write(LogLevel level,
                     const std::string& stage,
                     const std::string& message) noexcept = 0;
};

/// Progress of a run: the running stage ("estimate_epsilon", "detect_planes", "cell_complex",
/// "evidence", "solve_labeling", ...; each runs once per call) and its completed fraction in
/// [0, 1].
struct Progress {
  std::string stage;
  double stage_fraction = 0.0;
};

/// @brief Callbacks of one run. Progress and cancel callbacks may be called from any worker
/// thread but never concurrently (the library serialises them).
struct RunControl {
  /// Throttled to about 10 Hz per stage (first and last report of a stage always come). A
  /// callback that throws counts as a cancel request.
  std::function<void(const Progress&)> on_progress;
  /// Polled between chunks of work; returning true stops the run with kCancelled. Keep it
  /// cheap (an atomic load).
  std::function<bool()> is_cancelled;
  /// Log destination; null = silent.
  LogSink* log = nullptr;
};

}  // namespace v3
}  // namespace linesurf
