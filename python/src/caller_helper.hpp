// The helper thread on which an interruptible call of the Python module runs (interruptible.hpp),
// kept by its calling thread from one call to the next.
//
// Why kept: the helper runs the library's oneTBB loops, so it enters oneTBB as an external
// thread. A new std::thread per call made every call a new external thread, and a Python
// simulation on two threads grew by tens of MB over a few thousand steps (docs/simulation.md);
// one helper per calling thread, reused, does not. The cost is one idle thread (blocked on a
// condition variable, no CPU) per Python thread that has made a long call, joined when that
// thread ends.
#pragma once

#include <unistd.h>

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

namespace exactccd::python {

/// One helper thread that runs the tasks posted to it, one at a time, in order. Started on the
/// first post; stopped and joined by the destructor.
class CallerHelper {
 public:
  CallerHelper() = default;
  CallerHelper(const CallerHelper&) = delete;
  CallerHelper& operator=(const CallerHelper&) = delete;
  ~CallerHelper() {
    if (!thread_.joinable()) return;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  /// Runs task on the helper thread; returns at once. The caller waits for the task's own
  /// signal of completion (a future) before posting the next. Throws std::system_error when
  /// the system refuses to start the thread (then nothing runs).
  void post(std::function<void()> task) {
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      task_ = std::move(task);
    }
    wake_.notify_one();
  }

  /// The process this helper's thread belongs to (a forked child inherits the record, not the
  /// thread).
  [[nodiscard]] pid_t process() const { return process_; }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || task_ != nullptr; });
      if (stop_) return;
      const std::function<void()> task = std::exchange(task_, nullptr);
      lock.unlock();
      task();
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::function<void()> task_;
  bool stop_ = false;
  pid_t process_ = getpid();
  std::thread thread_;
};

/// The calling thread's helper. In a process forked after the parent's thread made a long call,
/// the inherited record names a thread that does not exist there (and its mutex may have been
/// held at the fork): it is abandoned, deliberately leaked (a few hundred bytes, once per
/// thread per fork), and a new helper made.
inline CallerHelper& caller_helper() {
  static thread_local std::unique_ptr<CallerHelper> helper;
  if (helper != nullptr && helper->process() != getpid()) {
    static_cast<void>(helper.release());  // NOLINT(bugprone-unused-return-value): leaked on purpose, above
  }
  if (helper == nullptr) helper = std::make_unique<CallerHelper>();
  return *helper;
}

}  // namespace exactccd::python
