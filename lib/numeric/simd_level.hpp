// The vector instruction set a batched stage runs with, chosen at run time (docs/performance.md,
// "Batched stages"): one build runs on every x86-64 CPU. A batched stage is written once as a
// loop over its lanes and compiled once per level (GCC target attributes); the answers are the
// same at every level, bit for bit (each lane does the scalar stage's operations, in its order,
// with the same rounding: no fused multiply-add, -ffp-contract=off).
#pragma once

#include <optional>
#include <string>

namespace exactccd::numeric {

/// The levels, lowest first: SSE2 (the x86-64 baseline: two doubles per instruction), AVX2
/// (four), AVX-512F (eight).
enum class SimdLevel { sse2 = 0, avx2 = 1, avx512 = 2 };

/// The level's name: "sse2", "avx2", "avx512".
const char* simd_level_name(SimdLevel level);

/// The level named `name` ("sse2", "avx2", "avx512"), or nothing.
std::optional<SimdLevel> simd_level_named(const std::string& name);

/// The highest level this CPU (and its operating system) supports.
SimdLevel detected_simd_level();

/// The level the library's batched stages use: the detected one, or the lower one named by the
/// environment variable EXACTCCD_SIMD (for tests and benchmarks; a level the CPU lacks, or an
/// unknown name, is not taken: see simd_level_text). Read once, at the first call.
SimdLevel simd_level();

/// One line for `exactccd --version` and `scene --stats`: the level in use and why, e.g.
/// "avx512 (detected)" or "sse2 (EXACTCCD_SIMD=sse2; the CPU has avx512)".
std::string simd_level_text();

}  // namespace exactccd::numeric
