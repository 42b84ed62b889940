#include "exact/stack_budget.hpp"

#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#define EXACTCCD_HAVE_PTHREAD_STACKSIZE 1
#endif

#include "filter/fp_environment.hpp"

namespace exactccd::exact {
namespace {

// Bytes per recursion level: 192 measured in a release build (gdb, x86-64, GCC 12), taken
// twice; sanitizers and unoptimised builds use several times more, so far more there.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr std::size_t kFrameBytes = 4096;
#else
constexpr std::size_t kFrameBytes = 384;
#endif
// The recursion may use half of a 1 MB thread stack on the caller's thread: with 384-byte
// levels, polynomials of up to 325-bit coefficients (every query of the shared unit tests,
// at most 240 bits, and of the bundled simulation sets, at most 320 bits, measured) stay on
// the caller's thread; a helper thread costs about as much as the CGAL path itself (measured:
// exact method on the unit tests 85 -> 177 us per query when every query used one).
constexpr std::size_t kCallerBudget = std::size_t{512} << 10;
constexpr std::size_t kBaseStack = std::size_t{1} << 20;       // everything but the recursion
constexpr std::size_t kDepthMargin = 64;

/// Bytes left on the calling thread's stack below this frame, or 0 when it cannot be told.
/// glibc reads the main thread's stack from its limit and /proc/self/maps (tens of
/// microseconds), so this is asked only for deep isolations.
std::size_t remaining_stack() {
#if defined(__GLIBC__)
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
  void* low = nullptr;
  std::size_t size = 0;
  const int got = pthread_attr_getstack(&attr, &low, &size);
  pthread_attr_destroy(&attr);
  if (got != 0) return 0;
  const char here = 0;
  const auto sp = reinterpret_cast<std::uintptr_t>(&here), bottom = reinterpret_cast<std::uintptr_t>(low);
  return sp > bottom ? sp - bottom : 0;
#else
  return 0;
#endif
}

}  // namespace

std::size_t descartes_depth_bound(std::size_t coefficient_bits) {
  return 4 * coefficient_bits + kDepthMargin;
}

void run_with_stack_for_depth(std::size_t depth, const std::function<void()>& work) {
  const std::size_t need = depth * kFrameBytes;
  // Inline when the recursion fits half of a 1 MB stack, or what this thread has left (with a
  // reserve for everything else): a main thread or a default glibc thread has 8 MB.
  if (need <= kCallerBudget || need + kBaseStack <= remaining_stack()) {
    work();
    return;
  }
#if defined(EXACTCCD_HAVE_PTHREAD_STACKSIZE)
  struct Job {
    const std::function<void()>* work;
    std::exception_ptr error;
  } job{&work, nullptr};
  const std::size_t bytes = kBaseStack + need;
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) throw std::runtime_error("exactccd: pthread_attr_init failed");
  const int sized = pthread_attr_setstacksize(&attr, bytes);
  pthread_t thread;
  const int started = sized != 0 ? sized : pthread_create(&thread, &attr, [](void* arg) -> void* {
    auto* j = static_cast<Job*>(arg);
    try {
      const filter::DefaultFpEnvironment fp_environment;  // a new thread's, made certain
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
