#include "tools/cli/cli_support.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <new>

namespace linesurf::cli {
namespace {

std::atomic<bool> g_interrupted{false};  // set by SIGINT/SIGTERM; the CLI owns the process

extern "C" void HandleSignal(int /*signal*/) { g_interrupted.store(true); }

}  // namespace

int ExitCodeFor(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidOptions: return kExitUsage;
    case ErrorCode::kInvalidInput: return kExitInvalidInput;
    case ErrorCode::kCancelled: return kExitCancelled;
    case ErrorCode::kDegenerate:  // valid input, but nothing to compute from (e.g. no plane)
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

int ReportError(const Error& error, const std::filesystem::path& file) {
  // An option out of range is not the file's fault; a message that names the file already is.
  if (error.code == ErrorCode::kInvalidOptions ||
      error.message.find(file.string()) != std::string::npos) {
    return ReportError(error);
  }
  Error named = error;
  named.message = file.string() + ": " + error.message;
  return ReportError(named);
}

RunControl CliRunControl(const CommonOptions& common) {
  std::signal(SIGINT, HandleSignal);
  std::signal(SIGTERM, HandleSignal);
  RunControl control;
  control.is_cancelled = [] { return g_interrupted.load(); };
  if (!common.quiet) {
    control.on_progress = [](const Progress& p) {
      std::fprintf(stderr, "\r[%s] %3d%%", p.stage.c_str(),
                   static_cast<int>(p.stage_fraction * 100.0 + 0.5));
      if (p.stage_fraction >= 1.0) std::fprintf(stderr, "\n");
      std::fflush(stderr);
    };
  }
  return control;
}

void PrintWarning(const CommonOptions& common, const std::string& message) {
  if (!common.quiet) std::cerr << "linesurf: warning: " << message << "\n";
}

int GuardedRun(const std::function<int()>& fn) {
  try {
    return fn();
  } catch (const std::bad_alloc&) {
    return ReportError(Error{ErrorCode::kResourceExhausted, "", "out of memory"});
  } catch (const std::exception& e) {
    return ReportError(Error{ErrorCode::kInternal, "", e.what()});
  }
}

int CheckStandardOutput(int code) {
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int flush_errno = errno;  // from the first failed write or flush
  if (flushed && std::cout && std::ferror(stdout) == 0) return code;
  std::cerr << "linesurf: error: standard output: write failed"
            << (flush_errno ? std::string(" (") + std::strerror(flush_errno) + ")" : "") << "\n";
  return code == kExitOk ? kExitInvalidInput : code;
}

Status WriteReport(const std::filesystem::path& path,
                   const nlohmann::ordered_json& report,
                   const std::string& stage) {
  std::ofstream out(path);
  out << report.dump(2) << "\n";
  out.close();
  if (!out) return Error{ErrorCode::kInvalidInput, stage, path.string() + ": cannot be written"};
  return {};
}

}  // namespace linesurf::cli
