#pragma once
// Runs work inside a oneTBB arena sized from RunContext::num_threads (never global_control).

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "engine/core/run_context.h"

namespace linesurf {

/// Threads an arena gets for `requested` (0 = automatic: the machine's concurrency). A request
/// is honoured up to the process's worker limit, tbb::global_control::max_allowed_parallelism,
/// which is the machine's concurrency unless the host raised it: an arena of more threads than
/// that limit would still run on the limit's threads (oneTBB caps its workers and warns on
/// stderr), so oversubscription is the host's decision (the CLI's -j N, the thread tests).
inline int ArenaConcurrency(int requested) {
  if (requested <= 0) return tbb::info::default_concurrency();
  const auto limit =
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(requested), limit));
}

template <typename Fn>
decltype(auto) RunInArena(const RunContext& ctx, Fn&& fn) {
  tbb::task_arena arena(ArenaConcurrency(ctx.num_threads));
  return arena.execute(std::forward<Fn>(fn));
}

}  // namespace linesurf
