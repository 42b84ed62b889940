#include "numeric/simd_level.hpp"

#include <cstdlib>

namespace exactccd::numeric {
namespace {

/// What simd_level() settles on, and the text that says why (computed once).
struct Choice {
  SimdLevel level;
  std::string text;
};

Choice choose() {
  const SimdLevel cpu = detected_simd_level();
  const char* asked = std::getenv("EXACTCCD_SIMD");
  if (asked == nullptr) return {cpu, std::string(simd_level_name(cpu)) + " (detected)"};
  const std::string because = std::string("EXACTCCD_SIMD=") + asked + "; the CPU has " + simd_level_name(cpu);
  const std::optional<SimdLevel> wanted = simd_level_named(asked);
  if (!wanted) return {cpu, std::string(simd_level_name(cpu)) + " (" + because + ": not a level, ignored)"};
  if (*wanted > cpu) return {cpu, std::string(simd_level_name(cpu)) + " (" + because + ": not available, ignored)"};
  return {*wanted, std::string(simd_level_name(*wanted)) + " (" + because + ")"};
}

const Choice& choice() {
  static const Choice chosen = choose();  // immutable once made; thread-safe initialisation
  return chosen;
}

}  // namespace

const char* simd_level_name(SimdLevel level) {
  switch (level) {
    case SimdLevel::sse2: return "sse2";
    case SimdLevel::avx2: return "avx2";
    case SimdLevel::avx512: return "avx512";
  }
  return "sse2";
}

std::optional<SimdLevel> simd_level_named(const std::string& name) {
  for (const SimdLevel level : {SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512})
    if (name == simd_level_name(level)) return level;
  return std::nullopt;
}

SimdLevel detected_simd_level() {
#if defined(__x86_64__) && defined(__GNUC__)
  // __builtin_cpu_supports also checks that the operating system saves the registers (XCR0).
  if (__builtin_cpu_supports("avx512f")) return SimdLevel::avx512;
  if (__builtin_cpu_supports("avx2")) return SimdLevel::avx2;
#endif
  return SimdLevel::sse2;
}

SimdLevel simd_level() { return choice().level; }

std::string simd_level_text() { return choice().text; }

}  // namespace exactccd::numeric
