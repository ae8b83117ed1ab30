#pragma once
// Runs work inside a oneTBB arena sized from RunContext::num_threads (never global_control).

#include <tbb/task_arena.h>

#include "engine/core/run_context.h"

namespace linesurf {

template <typename Fn>
decltype(auto) RunInArena(const RunContext& ctx, Fn&& fn) {
  tbb::task_arena arena(ctx.num_threads > 0 ? ctx.num_threads : tbb::task_arena::automatic);
  return arena.execute(std::forward<Fn>(fn));
}

}  // namespace linesurf
