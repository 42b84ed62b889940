// A small parallel loop over an index range, in chunks handed out dynamically (some CCD queries
// cost 100x others), for the scene narrow phase. No state outlives a call.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "exactccd/scene.hpp"
#include "numeric/fp_environment.hpp"

namespace exactccd::scene {

/// The cancellation flag of the scene call running on this thread (SceneOptions::cancel), for
/// parallel_chunks: a scene entry point installs its options' flag for the call's duration
/// (RAII, restored on exit, also when it throws); parallel_chunks passes it on to its workers,
/// which stop taking chunks once it is set, and then throws exactccd::Cancelled. Per thread and
/// scoped, like the floating-point environment guard: no state outlives a call.
class CancelScope {
 public:
  /// Installs `flag` (nullptr: not cancellable) on this thread until destruction.
  explicit CancelScope(const std::atomic<bool>* flag) : previous_(current_) { current_ = flag; }
  ~CancelScope() { current_ = previous_; }
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

  /// The flag installed on this thread, or nullptr.
  static const std::atomic<bool>* current() { return current_; }

 private:
  static inline thread_local const std::atomic<bool>* current_ = nullptr;
  const std::atomic<bool>* previous_;
};

/// What every public scene function opens first, for its whole call (docs/design.md, 8): the
/// floating-point environment the filters are proved in (numeric/fp_environment.hpp), installed
/// before anything compares a double (validation included: DAZ would read -2^-1074 as -0), and
/// the call's cancellation flag (SceneOptions::cancel; nullptr: not cancellable).
class SceneCall {
 public:
  /// Installs both for this scope.
  explicit SceneCall(const std::atomic<bool>* cancel = nullptr) : cancel_scope_(cancel) {}

 private:
  numeric::DefaultFpEnvironment fp_environment_;  // constructed first: members in this order
  CancelScope cancel_scope_;
};

/// True when `flag` is set (nullptr: never).
inline bool cancel_requested(const std::atomic<bool>* flag) {
  return flag != nullptr && flag->load(std::memory_order_relaxed);
}

/// The most threads a scene function uses (validate(SceneOptions) refuses more).
using exactccd::kMaxThreads;

/// The number of threads to use for `requested` (0: every hardware thread), in 1..kMaxThreads.
inline unsigned resolve_threads(unsigned requested) {
  if (requested == 0) requested = std::thread::hardware_concurrency();
  return std::clamp(requested, 1u, kMaxThreads);
}

/// Calls body(begin, end, worker) over chunks [begin, end) of [0, n) of at most `chunk`
/// indices, on up to `threads` threads (the calling thread is worker 0; workers are numbered
/// below the returned count, so per-worker outputs can be indexed by them). Chunks go to
/// whichever worker is free, so which worker runs which chunk is not deterministic: callers
/// merge per-worker outputs in an order of their own. body returns false to stop every worker
/// early (chunks already started finish). The first exception thrown by body stops the loop
/// and is rethrown here. When the system refuses a thread (std::system_error: a thread limit,
/// no memory for its stack), the workers started do all the chunks: same results, fewer
/// threads. Returns the number of workers that ran. Under a CancelScope whose flag gets set,
/// the workers stop between chunks and exactccd::Cancelled is thrown here.
template <class Body>
unsigned parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, Body&& body) {
  const std::atomic<bool>* cancel = CancelScope::current();
  chunk = std::max<std::size_t>(1, chunk);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const unsigned workers = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, chunks)));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&](unsigned worker) {
    // A new thread inherits its creator's floating-point environment: establish the default
    // one in every worker (a no-op on the calling thread, whose entry point already did).
    const numeric::DefaultFpEnvironment fp_environment;
    const CancelScope cancel_scope(cancel);  // nested loops of a worker see the same flag
    try {
      for (std::size_t c; !stop.load(std::memory_order_relaxed) && !cancel_requested(cancel) &&
                          (c = next.fetch_add(1)) < chunks;) {
        const std::size_t begin = c * chunk, end = std::min(n, begin + chunk);
        if (!body(begin, end, worker)) stop = true;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (unsigned w = 1; w < workers; ++w) {
    try {
      pool.emplace_back(work, w);
    } catch (const std::exception&) {  // no more threads (system_error, bad_alloc): the ones running do it all
      break;
    }
  }
  work(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (cancel_requested(cancel)) throw Cancelled();
  return static_cast<unsigned>(pool.size() + 1);
}

/// Calls body(begin, end) over pieces of [0, n) of `grain` indices on up to `threads` threads
/// (parallel_chunks), or once over all of [0, n) on the calling thread when n < 4 grain or
/// threads <= 1 (starting threads costs more than a short loop).
template <class Body>
void parallel_ranges(std::size_t n, unsigned threads, std::size_t grain, Body&& body) {
  if (threads <= 1 || n < 4 * grain) {
    if (cancel_requested(CancelScope::current())) throw Cancelled();
    body(std::size_t{0}, n);
    return;
  }
  parallel_chunks(n, threads, grain, [&](std::size_t begin, std::size_t end, unsigned) {
    body(begin, end);
    return true;
  });
}

}  // namespace exactccd::scene
