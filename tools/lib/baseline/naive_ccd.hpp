// The textbook method, NOT robust: the speed baseline and the example of what goes wrong near
// degeneracies (missed and invented collisions). Never use it where a wrong answer matters;
// the filtered and exact methods are exact. Variants: plain doubles, doubles with a
// Bridson-style tolerance (conservative: invents collisions rather than missing them), and
// the precision ladder (MPFR at 24, 53, 113 and 256 bits: more precision, still not exact).
// The algorithm is in naive_algorithm.hpp.
#pragma once

#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::baseline {

/// Which textbook variant.
enum class NaiveVariant { plain, tolerance, mpfr24, mpfr53, mpfr113, mpfr256 };

/// The tolerance of NaiveVariant::tolerance (relative to the scene scale), as in the common
/// practice of conservative CCD codes.
constexpr double kNaiveTolerance = 1e-6;

/// Naive vertex-face CCD (non-robust): the earliest root found to collide, if any.
std::optional<double> naive_toi(const VertexFaceQuery& q,
                                NaiveVariant variant = NaiveVariant::plain);

/// Naive edge-edge CCD (non-robust): the earliest root found to collide, if any.
std::optional<double> naive_toi(const EdgeEdgeQuery& q,
                                NaiveVariant variant = NaiveVariant::plain);

}  // namespace exactccd::baseline
