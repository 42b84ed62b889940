// The callers' floating-point environments of the environment tests (tests/api/
// test_fp_environment.cpp for the linear entry points, tests/rigid/test_rigid_fp_environment.cpp
// for the rigid ones): each environment, installing it, and the control state a call must leave
// as it found it (docs/design.md, 8).
#pragma once

#include <cfenv>
#include <cstdio>
#include <string>

#if defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#define EXACTCCD_TEST_X86_64 1
#endif

namespace exactccd::testing {

/// A caller's floating-point environment.
struct Environment {
  const char* name;
  int rounding;  ///< FE_TONEAREST, FE_UPWARD, ...
  bool ftz_daz;  ///< flush-to-zero and denormals-are-zero (what -ffast-math programs set)
  bool traps;    ///< invalid, division by zero and overflow unmasked (SIGFPE on each)
};

/// Every environment the tests install.
inline constexpr Environment kEnvironments[] = {
    {"upward", FE_UPWARD, false, false},
    {"downward", FE_DOWNWARD, false, false},
    {"towardzero", FE_TOWARDZERO, false, false},
    {"ftz_daz", FE_TONEAREST, true, false},
    {"ftz_daz_upward", FE_UPWARD, true, false},
    {"traps", FE_TONEAREST, false, true},
};

/// The control state of the calling thread (status flags excluded).
struct ControlState {
  unsigned mxcsr = 0;
  unsigned x87 = 0;
  int rounding = 0;
  bool operator==(const ControlState& o) const {
    return mxcsr == o.mxcsr && x87 == o.x87 && rounding == o.rounding;
  }
};

/// The calling thread's control state now.
inline ControlState control_state() {
  ControlState s;
#ifdef EXACTCCD_TEST_X86_64
  s.mxcsr = _mm_getcsr() & 0xFFC0u;
  unsigned short cw = 0;
  __asm__ volatile("fnstcw %0" : "=m"(cw));
  s.x87 = cw;
#endif
  s.rounding = std::fegetround();
  return s;
}

/// A control state for messages.
inline std::string describe(const ControlState& s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "mxcsr control 0x%x, x87 0x%x, fegetround %d", s.mxcsr, s.x87, s.rounding);
  return buf;
}

/// Whether the platform lets the test install the environment.
inline bool supported(const Environment& e) {
#ifdef EXACTCCD_TEST_X86_64
  (void)e;
  return true;
#else
  return !e.ftz_daz && !e.traps;
#endif
}

/// Installs e on the calling thread (from the default environment).
inline void install(const Environment& e) {
  std::fesetenv(FE_DFL_ENV);
  std::fesetround(e.rounding);
#ifdef EXACTCCD_TEST_X86_64
  if (e.ftz_daz) _mm_setcsr(_mm_getcsr() | 0x8040u);  // FTZ (bit 15), DAZ (bit 6)
  if (e.traps) feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
#endif
}

/// Back to the default environment at the end of a scope (also when an assertion returns).
struct RestoreDefault {
  ~RestoreDefault() { std::fesetenv(FE_DFL_ENV); }
};

}  // namespace exactccd::testing
