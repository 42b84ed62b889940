// The floating-point environment every filter of exactccd is proved in, established at each
// public entry point whatever the caller's thread has set, and restored on the way out.
//
// The error bounds of the filters (docs/design.md, 5 and 8) assume IEEE 754 binary64 with
// round-to-nearest-even and gradual underflow: Shewchuk-style static bounds, TwoSum and the
// double-double algorithms are unsound under directed rounding, and flush-to-zero /
// denormals-are-zero (set for the whole process by programs linked with -ffast-math) break
// every argument about subnormals (CGAL's Interval_nt included: a tiny positive product whose
// upward-rounded bound is flushed to +0 is no longer enclosed, and an exact [0, 0] no longer
// proves a zero).
// Unmasked exceptions would turn the filters' intended overflows into traps.
//
// The guard costs one read of the control registers when the caller is already in the default
// environment (the common case: nothing is written, so nothing is restored); otherwise it
// installs the default one (round to nearest, all exceptions masked, no FTZ/DAZ) and restores
// the caller's on destruction, also when an exception leaves the scope. Status flags (inexact,
// underflow, ...) raised while the caller's environment was the default one are left raised, as
// by any floating-point computation; after a switch they are restored as found.
#pragma once

#include <cfenv>

#if defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

namespace exactccd::numeric {

/// True iff the calling thread's floating-point control state is the IEEE default the filters
/// are proved in: round to nearest, every exception masked, and (where the hardware has them)
/// no flush-to-zero or denormals-are-zero.
inline bool is_default_fp_environment() noexcept {
#if defined(__x86_64__) || defined(_M_X64)
  // MXCSR: bits 0-5 are status flags (ignored); DAZ (6), the six exception masks (7-12),
  // rounding control (13-14) and FTZ (15) must read 0, 111111, 00, 0: 0x1F80.
  const unsigned mxcsr = _mm_getcsr();
  if ((mxcsr & 0xFFC0u) != 0x1F80u) return false;
#if defined(__GNUC__)
  // x87 control word (long double arithmetic: the Newton guesses): exception masks (0-5) set,
  // precision control (8-9) extended, rounding control (10-11) to nearest: 0x037F in the bits
  // 0x0F3F.
  unsigned short x87 = 0;
  __asm__ volatile("fnstcw %0" : "=m"(x87));
  if ((x87 & 0x0F3Fu) != 0x033Fu) return false;
#endif
  return true;
#elif defined(__aarch64__) && defined(__GNUC__)
  // FPCR: rounding mode (22-23), FZ (24), FZ16 (19), and the trap enables (8-12, 15) must be 0.
  const unsigned long fpcr = __builtin_aarch64_get_fpcr();
  return (fpcr & ((3ul << 22) | (1ul << 24) | (1ul << 19) | 0x9F00ul)) == 0;
#else
  // Portable fallback: only the rounding direction can be read; flush-to-zero is invisible to
  // standard C++ (documented as a platform limitation in the README).
  return std::fegetround() == FE_TONEAREST;
#endif
}

/// RAII: installs the default floating-point environment for the calling thread for the
/// guard's lifetime when it is not already in place, and restores the caller's one on
/// destruction. Not copyable; one per scope, nestable (an inner guard finds the default
/// environment and does nothing).
///
/// On x86-64 the control registers are switched directly (stmxcsr/ldmxcsr, fnstcw/fldcw: a few
/// nanoseconds), which is all a caller in directed rounding, in its own
/// CGAL::Protect_FPU_rounding or with FTZ/DAZ needs. Only when the caller has unmasked x87
/// exceptions is the whole environment saved and restored (fegetenv/fesetenv, ~250 ns), so that
/// no x87 status flag raised inside becomes a pending exception at the caller's next x87
/// instruction. Elsewhere fegetenv/fesetenv is used whenever the environment is not the default.
class DefaultFpEnvironment {
 public:
  DefaultFpEnvironment() noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
    mxcsr_ = _mm_getcsr();
    __asm__ volatile("fnstcw %0" : "=m"(x87_));
    const bool sse_default = (mxcsr_ & 0xFFC0u) == 0x1F80u;
    const bool x87_default = (x87_ & 0x0F3Fu) == 0x033Fu;
    if (sse_default && x87_default) return;
    if ((x87_ & 0x003Fu) != 0x003Fu) {  // unmasked x87 exceptions: the whole environment
      mode_ = Mode::whole_environment;
      std::fegetenv(&saved_);
      std::fesetenv(FE_DFL_ENV);
      return;
    }
    mode_ = Mode::control_registers;
    if (!sse_default) _mm_setcsr((mxcsr_ & 0x3Fu) | 0x1F80u);  // keep the status flags
    // The x87 status word too, so that flags raised by the long-double guesses inside are not
    // left behind (fnstsw is cheap; fnstenv/fldenv cost ~100 ns and are used on the way out
    // only when the caller had x87 flags raised).
    __asm__ volatile("fnstsw %0" : "=m"(x87_status_));
    const unsigned short default_x87 = 0x037F;
    __asm__ volatile("fldcw %0" : : "m"(default_x87));
#else
    if (is_default_fp_environment()) return;
    mode_ = Mode::whole_environment;
    std::fegetenv(&saved_);
    std::fesetenv(FE_DFL_ENV);
#endif
  }
  ~DefaultFpEnvironment() {
    switch (mode_) {
      case Mode::unchanged:
        break;
      case Mode::whole_environment:
        std::fesetenv(&saved_);
        break;
      case Mode::control_registers:
#if defined(__x86_64__) && defined(__GNUC__)
        _mm_setcsr(mxcsr_);  // the caller's control bits and status flags, as found
        // The caller's x87 status flags and control word, as found (every exception masked in
        // this mode, so no restored flag can become a pending exception).
        if ((x87_status_ & 0x7Fu) == 0) {
          __asm__ volatile("fnclex");
        } else {
          X87Environment env;
          __asm__ volatile("fnstenv %0" : "=m"(env));
          env.status = static_cast<unsigned short>((env.status & ~0x7Fu) | (x87_status_ & 0x7Fu));
          __asm__ volatile("fldenv %0" : : "m"(env));
        }
        __asm__ volatile("fldcw %0" : : "m"(x87_));
#endif
        break;
    }
  }
  DefaultFpEnvironment(const DefaultFpEnvironment&) = delete;
  DefaultFpEnvironment& operator=(const DefaultFpEnvironment&) = delete;

  /// Whether the caller's environment differed from the default (and is restored at the end).
  bool changed() const noexcept { return mode_ != Mode::unchanged; }

 private:
  enum class Mode { unchanged, control_registers, whole_environment };
  Mode mode_ = Mode::unchanged;
  std::fenv_t saved_{};
#if defined(__x86_64__) && defined(__GNUC__)
  unsigned mxcsr_ = 0;
  unsigned short x87_ = 0;
  unsigned short x87_status_ = 0;
  /// fnstenv's 32-bit protected-mode layout (28 bytes): only the status word is edited.
  struct X87Environment {
    unsigned short control, unused0, status, unused1;
    unsigned char rest[20];
  };
  static_assert(sizeof(X87Environment) == 28, "the x87 environment is 28 bytes");
#endif
};

}  // namespace exactccd::numeric
