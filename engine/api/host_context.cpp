#include "engine/api/host_context.h"

namespace linesurf::api {

HostContext::HostContext(const RunControl& control, int num_threads) : control_(control) {
  ctx_.num_threads = num_threads;
  ctx_.log = control.log;
  if (control.is_cancelled) {
    ctx_.is_cancelled = [this] {
      std::lock_guard<std::mutex> lock(mutex_);
      try {
        return control_.is_cancelled();
      } catch (...) {
        return true;
      }
    };
  }
  if (control.on_progress) {
    // RunContext::ReportProgress throttles and turns a throwing callback into a cancel request.
    ctx_.on_progress = [this](const Progress& p) {
      std::lock_guard<std::mutex> lock(mutex_);
      control_.on_progress(p);
    };
  }
}

}  // namespace linesurf::api
