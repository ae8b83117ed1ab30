#pragma once
// Per-stage wall times and the process's peak memory, for run reports.

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace linesurf {

/// Records (stage, seconds) in the order stages end.
class StageTimer {
 public:
  /// Starts timing `stage`; the previous stage (if any) ends now.
  void Start(std::string stage);
  /// Ends the current stage.
  void Stop();
  [[nodiscard]] const std::vector<std::pair<std::string, double>>& Stages() const { return stages_; }
  [[nodiscard]] double TotalSeconds() const;

 private:
  std::string current_;
  std::chrono::steady_clock::time_point start_{};
  std::vector<std::pair<std::string, double>> stages_;
};

/// Peak resident set size of this process so far, in bytes (0 if unknown).
std::size_t PeakRssBytes();

}  // namespace linesurf
