#pragma once
// Thread-count tests that really run on the counts they name: the process's worker limit is
// raised above the core count (oversubscription on purpose), and a probe measures how many
// threads an arena of the library really runs at once.

#include <tbb/global_control.h>

namespace linesurf::testing {

/// Raises the process's worker limit to `threads` for the lifetime of the object, so that
/// RunInArena(ctx with num_threads <= threads) gets that many threads even on two cores.
class Oversubscribe {
 public:
  explicit Oversubscribe(int threads);

 private:
  tbb::global_control control_;
};

/// The counts thread-count tests compare with a 1-thread run: even, odd, and far above the two
/// CI cores.
inline constexpr int kThreadCounts[] = {2, 3, 8};

/// Holds the worker limit at 8 for its lifetime and checks (as gtest failures) that arenas of
/// 1, 2, 3 and 8 threads really run that many threads at once. Construct one at the start of a
/// thread-count test.
class RealThreadCounts {
 public:
  RealThreadCounts();

 private:
  Oversubscribe oversubscribe_;
};

/// The largest number of tasks that ran at the same time in RunInArena(ctx.num_threads =
/// threads) when `threads` tasks each wait (up to 10 s) for all the others to start: equal to
/// `threads` exactly when the arena really has that concurrency.
int ObservedConcurrency(int threads);

}  // namespace linesurf::testing
