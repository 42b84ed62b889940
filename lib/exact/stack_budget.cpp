#include "exact/stack_budget.hpp"

#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#include <unistd.h>
#define EXACTCCD_HAVE_PTHREAD_STACKSIZE 1
#endif

#include "numeric/fp_environment.hpp"

namespace exactccd::exact {
namespace {

// Bytes per recursion level: 192 measured in a release build (gdb, x86-64, GCC 12), taken
// twice; sanitizers and unoptimised builds use several times more, so far more there.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr std::size_t kFrameBytes = 4096;
#else
constexpr std::size_t kFrameBytes = 384;
#endif
// Where the calling thread's stack cannot be measured (off glibc), the recursion may use this
// much of it inline: 64 KB (a musl thread has 128 KB, a macOS secondary thread 512 KB).
constexpr std::size_t kUnmeasuredBudget = std::size_t{64} << 10;
// What the rest of a query and the caller keep of the stack besides the recursion.
constexpr std::size_t kReserve = std::size_t{256} << 10;
constexpr std::size_t kBaseStack = std::size_t{1} << 20;       // everything but the recursion
constexpr std::size_t kDepthMargin = 64;

/// The calling thread's stack [low, low + size), measured once per thread (glibc reads the
/// main thread's from its limit and /proc/self/maps: tens of microseconds); size 0 when it
/// cannot be told. A per-thread fact, not shared state.
struct StackBounds {
  std::uintptr_t low = 0;
  std::size_t size = 0;
};

StackBounds measure_stack() {
#if defined(__GLIBC__)
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return {};
  void* low = nullptr;
  std::size_t size = 0;
  const int got = pthread_attr_getstack(&attr, &low, &size);
  pthread_attr_destroy(&attr);
  if (got != 0) return {};
  return {reinterpret_cast<std::uintptr_t>(low), size};
#else
  return {};
#endif
}

/// Bytes left on the calling thread's stack below this frame; 0 when unknown, or when this
/// frame is not on the thread's own stack (a fiber, a coroutine, a signal stack).
std::size_t remaining_stack() {
  thread_local const StackBounds bounds = measure_stack();
  if (bounds.size == 0) return 0;
  const char here = 0;
  const auto sp = reinterpret_cast<std::uintptr_t>(&here);
  if (sp <= bounds.low || sp > bounds.low + bounds.size) return 0;
  return sp - bounds.low;
}

}  // namespace

std::size_t descartes_depth_bound(std::size_t coefficient_bits) {
  return 4 * coefficient_bits + kDepthMargin;
}

std::size_t descartes_depth_bound(std::size_t coefficient_bits, int degree) {
  if (degree <= 4) return descartes_depth_bound(coefficient_bits);
  if (degree > 15) throw std::logic_error("exactccd: descartes_depth_bound: degree above 15");
  const std::size_t n = static_cast<std::size_t>(degree);
  std::size_t ceil_log2_n = 0;
  while ((std::size_t{1} << ceil_log2_n) < n) ++ceil_log2_n;
  return n * coefficient_bits + (n - 1) * (n + 6) + (n + 2) / 2 * ceil_log2_n + ceil_log2_n + 4 + kDepthMargin;
}

void run_with_stack_for_depth(std::size_t depth, const std::function<void()>& work) {
  const std::size_t need = depth * kFrameBytes;
  // Inline when the recursion fits what this thread has left with a reserve to spare (a main
  // thread or a default glibc thread has 8 MB), or a small budget where that is unknown.
  const std::size_t left = remaining_stack();
  if (left > 0 ? need + kReserve <= left : need <= kUnmeasuredBudget) {
    work();
    return;
  }
#if defined(EXACTCCD_HAVE_PTHREAD_STACKSIZE)
  struct Job {
    const std::function<void()>* work;
    std::exception_ptr error;
  } job{&work, nullptr};
  // A whole number of pages: some systems (macOS) refuse any other stack size.
  const long page_size = sysconf(_SC_PAGESIZE);
  const std::size_t page = page_size > 0 ? static_cast<std::size_t>(page_size) : 4096;
  const std::size_t bytes = (kBaseStack + need + page - 1) / page * page;
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) throw std::runtime_error("exactccd: pthread_attr_init failed");
  const int sized = pthread_attr_setstacksize(&attr, bytes);
  pthread_t thread;
  const int started = sized != 0 ? sized : pthread_create(&thread, &attr, [](void* arg) -> void* {
    auto* j = static_cast<Job*>(arg);
    try {
      const numeric::DefaultFpEnvironment fp_environment;  // a new thread's, made certain
      (*j->work)();
    } catch (...) {
      j->error = std::current_exception();
    }
    return nullptr;
  }, &job);
  pthread_attr_destroy(&attr);
  if (started != 0)
    throw std::runtime_error("exactccd: cannot start a thread with the " +
                             std::to_string(bytes >> 20) +
                             " MB stack that exact root isolation needs for this query");
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
#else
  work();  // no way to size a thread's stack here: documented platform limitation
#endif
}

}  // namespace exactccd::exact
