#include "tools/cli/cli_support.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "engine/core/exception.h"

namespace linesurf::cli {
namespace {

std::atomic<bool> g_interrupted{false};  // set by SIGINT/SIGTERM; the CLI owns the process

extern "C" void HandleSignal(int /*signal*/) { g_interrupted.store(true); }

}  // namespace

int ExitCodeFor(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidOptions: return kExitUsage;
    case ErrorCode::kInvalidInput:
    case ErrorCode::kDegenerate: return kExitInvalidInput;
    case ErrorCode::kCancelled: return kExitCancelled;
    case ErrorCode::kSolverFailed:
    case ErrorCode::kResourceExhausted: return kExitFailed;
    case ErrorCode::kInternal: return kExitInternal;
  }
  return kExitInternal;
}

int ReportError(const Error& error) {
  std::cerr << "linesurf: error: " << error.ToString() << "\n";
  return ExitCodeFor(error.code);
}

void ConfigureRunContext(const CommonOptions& common, RunContext& ctx) {
  std::signal(SIGINT, HandleSignal);
  std::signal(SIGTERM, HandleSignal);
  ctx.num_threads = common.threads;
  ctx.is_cancelled = [] { return g_interrupted.load(); };
  if (!common.quiet) {
    ctx.on_progress = [](const Progress& p) {
      std::fprintf(stderr, "\r[%s] %3d%%", p.stage.c_str(),
                   static_cast<int>(p.stage_fraction * 100.0 + 0.5));
      if (p.stage_fraction >= 1.0) std::fprintf(stderr, "\n");
      std::fflush(stderr);
    };
  }
}

void PrintWarning(const CommonOptions& common, const std::string& message) {
  if (!common.quiet) std::cerr << "linesurf: warning: " << message << "\n";
}

int GuardedRun(const std::function<int()>& fn) {
  try {
    return fn();
  } catch (const LinesurfException& e) {
    return ReportError(e.error());
  } catch (const std::bad_alloc&) {
    return ReportError(Error{ErrorCode::kResourceExhausted, "", "out of memory"});
  } catch (const std::exception& e) {
    return ReportError(Error{ErrorCode::kInternal, "", e.what()});
  }
}

Status WriteReport(const std::string& path, const nlohmann::json& report,
                   const std::string& stage) {
  std::ofstream out(path);
  out << report.dump(2) << "\n";
  out.close();
  if (!out) return Error{ErrorCode::kInvalidInput, stage, "cannot write report " + path};
  return {};
}

}  // namespace linesurf::cli
