#pragma once
// The CLI's run callbacks as an engine RunContext, for the subcommands that call engine modules
// directly (evaluate, arrange); the scene commands hand CliRunControl to the facade.

#include "engine/core/run_context.h"
#include "tools/cli/cli_support.h"

namespace linesurf::cli {

/// A RunContext with CliRunControl's callbacks and the --threads count.
inline void ConfigureRunContext(const CommonOptions& common, RunContext& ctx) {
  RunControl control = CliRunControl(common);
  ctx.num_threads = common.threads;
  ctx.on_progress = std::move(control.on_progress);
  ctx.is_cancelled = std::move(control.is_cancelled);
}

}  // namespace linesurf::cli
