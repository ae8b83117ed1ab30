#include "tools/python/python_run_control.h"

#include <condition_variable>
#include <exception>
#include <string>
#include <thread>
#include <utility>

namespace linesurf::python {
namespace {

const char* LevelName(LogLevel level) {
  switch (level) {
    case LogLevel::kDebug:
      return "debug";
    case LogLevel::kInfo:
      return "info";
    case LogLevel::kWarning:
      return "warning";
    case LogLevel::kError:
      return "error";
  }
  return "unknown";
}

}  // namespace

// Forwards the library's log lines to the Python callable (under the GIL, so serialised).
class PythonRunControl::Sink final : public LogSink {
 public:
  explicit Sink(PythonRunControl& owner) : owner_(owner) {}

  void Write(LogLevel level,
             const std::string& stage,
             const std::string& message) noexcept override {
    py::gil_scoped_acquire gil;
    try {
      owner_.log_(LevelName(level), stage, message);
    } catch (py::error_already_set& error) {
      owner_.KeepErrorAndCancel(std::move(error));
    } catch (...) {
      owner_.cancel_ = true;
    }
  }

 private:
  PythonRunControl& owner_;
};

PythonRunControl::PythonRunControl(py::object progress, py::object log)
    : progress_(std::move(progress)), log_(std::move(log)) {}

PythonRunControl::~PythonRunControl() = default;

void PythonRunControl::KeepErrorAndCancel(py::error_already_set&& error) {
  if (!pending_) pending_.emplace(std::move(error));
  cancel_ = true;
}

void PythonRunControl::RaisePending() {
  if (!pending_) return;
  py::error_already_set error = std::move(*pending_);
  pending_.reset();
  throw error;
}

void PythonRunControl::RunReleased(const std::function<void(const RunControl&)>& call) {
  Sink sink(*this);
  RunControl control;
  if (!progress_.is_none()) {
    control.on_progress = [this](const Progress& p) {
      py::gil_scoped_acquire gil;
      try {
        if (py::bool_(progress_(p.stage, p.stage_fraction))) cancel_ = true;
      } catch (py::error_already_set& error) {
        KeepErrorAndCancel(std::move(error));
      }
    };
  }
  control.is_cancelled = [this] { return cancel_.load(); };
  control.log = log_.is_none() ? nullptr : &sink;

  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        call(control);
      } catch (...) {
        failure = std::current_exception();  // bad_alloc storing the result
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, kSignalPollInterval, [&] { return done; })) {
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) KeepErrorAndCancel(py::error_already_set());
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace linesurf::python
