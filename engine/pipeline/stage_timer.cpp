#include "engine/pipeline/stage_timer.h"

#include <sys/resource.h>

namespace linesurf {

void StageTimer::Start(std::string stage) {
  Stop();
  current_ = std::move(stage);
  start_ = std::chrono::steady_clock::now();
}

void StageTimer::Stop() {
  if (current_.empty()) return;
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
  stages_.emplace_back(std::move(current_), elapsed.count());
  current_.clear();
}

double StageTimer::TotalSeconds() const {
  double total = 0.0;
  for (const auto& stage : stages_) total += stage.second;
  return total;
}

std::size_t PeakRssBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

}  // namespace linesurf
