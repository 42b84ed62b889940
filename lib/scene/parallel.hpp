// The parallel loops of the library on oneTBB (Debian's libtbb-dev): every scene function, the
// functions over a caller's candidates, the rigid scene and the Python batches run their loops
// through parallel_chunks, inside with_threads, so that
// - `threads` bounds the concurrency: a call runs in the caller's task arena when that arena
//   is no larger (inside a simulator's tbb::parallel_for body its loops share the simulator's
//   threads, never start their own: no oversubscription), else in a task arena of `threads`
//   slots used by this call alone (no two external threads wait for one arena's slot: no
//   deadlock); one thread runs everything on the calling thread, without TBB;
// - each loop is isolated (tbb::this_task_arena::isolate): a thread waiting for it takes only
//   its pieces, never an unrelated task of the caller that would run on top of its stack;
// - cancellation (SceneOptions::cancel, the Python module's Ctrl-C) and an early exit stop the
//   loop through its tbb::task_group_context (cancel_group_execution), exceptions propagate
//   (TBB rethrows the first), and every task body runs under the default floating-point
//   environment (TBB reuses its worker threads, so the guard is installed per task body).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <utility>

#include "exactccd/scene.hpp"
#include "numeric/fp_environment.hpp"

namespace exactccd::scene {

/// The cancellation flag of the scene call running on this thread (SceneOptions::cancel), for
/// parallel_chunks: a scene entry point installs its options' flag for the call's duration
/// (RAII, restored on exit, also when it throws); parallel_chunks passes it on to every task
/// body, which stops the loop once it is set, and then throws exactccd::Cancelled. Per thread
/// and scoped, like the floating-point environment guard: no state outlives a call.
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

/// A value kept across calls (SceneBroadPhase's task arena, a stream's buffers) and lent to one
/// call at a time: a call that finds it lent out uses one of its own instead, so concurrent
/// calls stay correct and a lone caller reuses the value (allocating nothing once it is grown).
template <class T>
class Kept {
 public:
  /// Constructs the kept value from `args`.
  template <class... Args>
  explicit Kept(Args&&... args) : value_(std::forward<Args>(args)...) {}
  Kept(const Kept&) = delete;
  Kept& operator=(const Kept&) = delete;

  /// The kept value while the loan lives, when no other loan holds it (get() is null
  /// otherwise, or when `kept` is null).
  class Loan {
   public:
    /// Borrows from `kept` (may be null).
    explicit Loan(Kept* kept)
        : kept_(kept != nullptr && !kept->lent_.exchange(true, std::memory_order_acquire) ? kept : nullptr) {}
    ~Loan() {
      if (kept_ != nullptr) kept_->lent_.store(false, std::memory_order_release);
    }
    Loan(const Loan&) = delete;
    Loan& operator=(const Loan&) = delete;
    /// The borrowed value, or nullptr.
    T* get() const { return kept_ != nullptr ? &kept_->value_ : nullptr; }

   private:
    Kept* kept_;
  };

 private:
  T value_;
  std::atomic<bool> lent_{false};
};

/// A task arena of a call's thread count kept across calls (SceneBroadPhase).
using KeptArena = Kept<tbb::task_arena>;

/// f() with its parallel loops (parallel_chunks) on at most `threads` threads: on the calling
/// thread alone when threads <= 1; in the calling thread's task arena when that arena has at
/// most `threads` slots (composing with a caller's TBB loops); else in `kept` (an arena of
/// `threads` slots) when given and not lent to another call, else in a task arena of `threads`
/// slots made for this call. The calling thread runs f in every case (the arena's reserved slot
/// is free: one call per arena), under the default floating-point environment and this thread's
/// cancellation flag; f's exception propagates.
template <class F>
auto with_threads(unsigned threads, F&& f, KeptArena* kept = nullptr) -> decltype(f()) {
  if (threads <= 1 || tbb::this_task_arena::max_concurrency() <= static_cast<int>(threads)) return f();
  const std::atomic<bool>* cancel = CancelScope::current();
  const auto in_arena = [&]() -> decltype(f()) {
    const numeric::DefaultFpEnvironment fp_environment;
    const CancelScope cancel_scope(cancel);
    return f();
  };
  const KeptArena::Loan loan(kept);
  if (tbb::task_arena* arena = loan.get()) return arena->execute(in_arena);
  tbb::task_arena arena(static_cast<int>(threads));
  return arena.execute(in_arena);
}

/// The number of per-worker slots a loop of parallel_chunks(..., threads, ...) started here
/// needs: its worker indices are below it (1 when threads <= 1; else the slots of the current
/// task arena, which TBB makes at least 2).
inline unsigned worker_slots(unsigned threads) {
  if (threads <= 1) return 1;
  return static_cast<unsigned>(std::max(2, tbb::this_task_arena::max_concurrency()));
}

/// A per-worker output on a cache line of its own (alignas(64)): workers writing their own
/// outputs side by side in a vector do not slow each other down by sharing a line.
template <class T>
struct alignas(64) PerWorker {
  T value{};  ///< the worker's output
};

/// Calls body(begin, end, worker) over chunks [begin, end) of [0, n) of at most `chunk` indices,
/// in the current task arena (tbb::parallel_for over the chunks, one task each: the simple
/// partitioner with grain 1, since the callers size their chunks; a thread takes the next
/// chunk when it is done with one, so a chunk full of expensive queries does not hold the
/// others back, as the pool's shared counter did before), isolated; on the calling thread alone, in order, when threads <= 1 or there
/// is one chunk. `worker` (this_task_arena::current_thread_index(), 0 on one thread) is below
/// worker_slots(threads) taken here and no two bodies running at once share it, so per-worker
/// outputs can be indexed by it; which worker runs which chunk is not deterministic: callers
/// merge per-worker outputs in an order of their own. body returns false to stop the loop
/// early (chunks already started finish). The first exception thrown by body stops the loop
/// and is rethrown here. Under a CancelScope whose flag gets set, the loop stops between
/// chunks and exactccd::Cancelled is thrown here, as it is when an enclosing TBB task group is
/// cancelled (no partial result is returned).
template <class Body>
void parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, Body&& body) {
  const std::atomic<bool>* cancel = CancelScope::current();
  chunk = std::max<std::size_t>(1, chunk);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const auto run = [&](std::size_t c, unsigned worker) {
    const std::size_t begin = c * chunk;
    return body(begin, std::min(n, begin + chunk), worker);
  };
  if (threads <= 1 || chunks <= 1) {
    for (std::size_t c = 0; c < chunks && !cancel_requested(cancel); ++c)
      if (!run(c, 0)) break;
    if (cancel_requested(cancel)) throw Cancelled();
    return;
  }
  tbb::task_group_context context;  // bound to the enclosing task's group: cancelled with it
  std::atomic<bool> stopped{false};
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, chunks, 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          const numeric::DefaultFpEnvironment fp_environment;  // per task body: workers are reused
          const CancelScope cancel_scope(cancel);              // for loops nested in body
          const unsigned worker = static_cast<unsigned>(tbb::this_task_arena::current_thread_index());
          for (std::size_t c = range.begin(); c != range.end(); ++c) {
            if (context.is_group_execution_cancelled()) return;
            if (cancel_requested(cancel)) {
              context.cancel_group_execution();
              return;
            }
            if (!run(c, worker)) {
              stopped.store(true);
              context.cancel_group_execution();
              return;
            }
          }
        },
        tbb::simple_partitioner(), context);
  });
  if (cancel_requested(cancel)) throw Cancelled();
  if (context.is_group_execution_cancelled() && !stopped.load()) throw Cancelled();
}

/// parallel_chunks(n, threads, chunk, body) as a whole call on at most `threads` threads
/// (with_threads around it): for a call that runs one loop (the rigid scene's narrow phase, the
/// Python module's batches, the command line's batches).
template <class Body>
void call_chunks(std::size_t n, unsigned threads, std::size_t chunk, Body&& body) {
  with_threads(threads, [&] { parallel_chunks(n, threads, chunk, body); });
}

/// Calls body(begin, end) over pieces of [0, n) of `grain` indices (parallel_chunks), or once
/// over all of [0, n) on the calling thread when n < 4 grain or threads <= 1 (handing out
/// pieces costs more than a short loop).
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
