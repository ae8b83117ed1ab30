#include "tests/support/thread_count.h"

#include "engine/core/parallel.h"

#include <gtest/gtest.h>
#include <tbb/task_group.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace linesurf::testing {

Oversubscribe::Oversubscribe(int threads)
    : control_(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads)) {}

RealThreadCounts::RealThreadCounts() : oversubscribe_(8) {
  for (const int threads : {1, 2, 3, 8}) {
    EXPECT_EQ(ObservedConcurrency(threads), threads) << "an arena of " << threads << " threads";
  }
}

int ObservedConcurrency(int threads) {
  RunContext ctx;
  ctx.num_threads = threads;
  std::atomic<int> running{0};
  std::atomic<int> most{0};
  RunInArena(ctx, [&] {
    tbb::task_group group;
    for (int t = 0; t < threads; ++t) {
      group.run([&] {
        const int now = ++running;
        for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        // Waits for the others; the deadline only ends a probe that cannot succeed.
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (most.load() < threads && std::chrono::steady_clock::now() < deadline) {
          std::this_thread::yield();
        }
        --running;
      });
    }
    group.wait();
  });
  return most.load();
}

}  // namespace linesurf::testing
