// Ctrl-C in long calls of the Python module: the work runs on a helper thread with the GIL
// released while the interpreter's thread checks for signals every 100 ms; on a signal whose
// handler raises (KeyboardInterrupt for Ctrl-C) it sets the call's cancellation flag
// (SceneOptions::cancel, or the batch loop's CancelScope), waits for the workers to stop (they
// stop between chunks of a few hundred queries, the loop's oneTBB task group cancelled: well
// under a second) and raises that exception. The helper is a plain thread, not a oneTBB worker:
// the interpreter's thread must stay free to poll for signals, and oneTBB may have no worker to
// spare (one core); each calling thread keeps its helper for its next call (caller_helper.hpp).
// oneTBB keeps its idle worker threads for the next call.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <memory>
#include <system_error>
#include <thread>
#include <utility>

#include "caller_helper.hpp"
#include "exactccd/scene.hpp"
#include "scene/parallel.hpp"

namespace exactccd::python {

/// How often the waiting interpreter thread checks for signals.
constexpr std::chrono::milliseconds kSignalPollInterval{100};

/// f(cancel) (cancel: a const std::atomic<bool>* that f's work must honour) run on a helper
/// thread, interruptible as described above. f's exception, if any, is rethrown here; after a
/// signal, the signal handler's exception is raised whatever f did. Without a thread to spare
/// (the system refuses one), f runs on this thread, not interruptible. Called with the GIL.
template <class F>
auto interruptible(F&& f) {
  namespace py = pybind11;
  using Result = decltype(f(static_cast<const std::atomic<bool>*>(nullptr)));
  std::atomic<bool> cancel{false};
  // Shared: the helper destroys its copy of the task after the result is set.
  const auto task = std::make_shared<std::packaged_task<Result()>>([&] { return f(&cancel); });
  std::future<Result> result = task->get_future();
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    bool on_helper = true;
    try {
      caller_helper().post([task] { (*task)(); });
    } catch (const std::system_error&) {
      on_helper = false;
      (*task)();  // no thread to spare: here, not interruptible
    }
    while (on_helper && result.wait_for(kSignalPollInterval) != std::future_status::ready) {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {  // the handler raised: its exception is now set
        interrupted = true;
        cancel.store(true);
        break;
      }
    }
    result.wait();  // the workers stop soon after the flag is set
  }
  if (interrupted) throw py::error_already_set();
  return result.get();
}

/// Queries per chunk of the loop (oneTBB, scene/parallel.hpp): small enough to balance queries of very different
/// cost (an exact fallback costs 100x a filtered answer), large enough to amortise the hand-out.
constexpr std::size_t kChunk = 64;

/// Batches of at most this many queries run on the calling thread (a few milliseconds at most
/// for filtered answers), larger ones interruptibly (a helper thread, about 50 us to start).
constexpr std::size_t kInterruptibleBatch = 4096;

/// body(begin, end) over chunks of [0, n) on at most `workers` threads (scene::call_chunks:
/// oneTBB), the GIL released; a batch of more than kInterruptibleBatch queries runs
/// interruptibly (Ctrl-C). Called with the GIL.
template <class Body>
void run_batch(std::size_t n, unsigned workers, Body&& body) {
  const auto loop = [&](const std::atomic<bool>* cancel) {
    const scene::CancelScope cancel_scope(cancel);  // the loop's task group is cancelled when it is set
    scene::call_chunks(n, workers, kChunk, [&](std::size_t begin, std::size_t end, unsigned) {
      body(begin, end);
      return true;
    });
    return true;
  };
  if (n > kInterruptibleBatch) {
    interruptible(loop);
  } else {
    pybind11::gil_scoped_release release;
    loop(nullptr);
  }
}

/// f(options with the call's cancellation flag), interruptible: a scene call. Called with the GIL.
template <class F>
auto with_cancel(const SceneOptions& options, F&& f) {
  return interruptible([&](const std::atomic<bool>* cancel) {
    SceneOptions o = options;
    o.cancel = cancel;
    return f(o);
  });
}

}  // namespace exactccd::python
