#pragma once
// Runs work inside a oneTBB arena sized from RunContext::num_threads (never global_control).

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "engine/core/run_context.h"

namespace linesurf {

/// Threads an arena gets for `requested` (0 = automatic). Requests above the machine's
/// concurrency are capped: oneTBB would otherwise print a warning on stderr, and results do not
/// depend on the thread count anyway.
inline int ArenaConcurrency(int requested) {
  const int available = tbb::info::default_concurrency();
  return requested > 0 ? std::min(requested, available) : available;
}

template <typename Fn>
decltype(auto) RunInArena(const RunContext& ctx, Fn&& fn) {
  tbb::task_arena arena(ArenaConcurrency(ctx.num_threads));
  return arena.execute(std::forward<Fn>(fn));
}

}  // namespace linesurf
