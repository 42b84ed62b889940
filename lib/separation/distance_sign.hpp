// The certified sign of a feature pair's distance polynomial f (separation_terms.hpp) at a
// double time t, in double-double arithmetic (filter/double_word.hpp), without GMP.
//
// Used by the interval stage's narrowing of a minimum-separation TOI (interval_separation.hpp):
// at the doubles next to a root of f, intervals in doubles cannot give f's sign (its value is
// about 2^-53 of the size of its terms); double-double with a running error bound almost
// always can (tests/test_distance_sign.cpp counts it), without GMP.
//
// f is evaluated from the geometry at t (feature_condition on values, as distance_at), never
// from its power-basis coefficients: the vector from point i to point j at t is
// (v0 - u0) + t ((v1 - u1) - (v0 - u0)), the two differences at t0 and t1 exact (TwoSum), so
// the error bound is relative to the primitives' local size, not to the coordinates' or the
// coefficients'.
//
// Scaling: f is homogeneous in lengths (degree 2 for point-point, 4 for point-edge, 6 for
// point-triangle and edge-edge, d counted as a length), so multiplying every coordinate and d
// by 2^s multiplies f by 2^(k s), k in {2, 4, 6}: a positive factor, the sign is unchanged.
// Before evaluating, every input is scaled by the power of two 2^s that brings the largest
// coordinate magnitude M into [1, 2). A product by a power of two is exact when its result is
// representable without rounding: scaling up (s > 0) never overflows (the coordinates become
// below 2) and never creates bits below 2^-1074, so it is exact (done in two factors when 2^s
// is not a double); scaling down (s < 0) is exact unless the result is subnormal, and such a
// coordinate is scaled back and compared: an inexact one gives "not certified". d is scaled
// likewise: when d 2^s >= 2^-500 it is normal, so exact; when d 2^s > 2^400 the call gives
// "not certified"; when d 2^s < 2^-500 (d negligible against the coordinates) its square is
// not formed: d^2 2^(2s) is in [0, 2^-1000], represented by the value 0 with the error bound
// 2^-1000 (a valid Approx whatever the rounding of d 2^s: rounding is monotone). So:
//   Overflow: every scaled coordinate is below 2 in magnitude; every difference at t0 or t1
//   below 4, the difference of those below 8, the value at t in [0, 1] below 12 < 2^4 (error
//   bounds far smaller). The largest expressions are degree 6: edge-edge w = da x db has
//   components below 2 * 2^8 = 2^9, h = w.r below 3 * 2^13 < 2^15, h^2 below 2^30;
//   s = (r x db).w and u below 3 * 2^9 * 2^9 < 2^20, |w|^2 below 2^20; d^2 <= 2^800, so
//   d^2 |w|^2 below 2^820; point-triangle likewise (n = e1 x e2 below 2^9, n.(p - a) below
//   2^15), point-edge and point-point smaller. Error bounds are of the same order (each a sum
//   of products of magnitudes and bounds of the operands, plus kRelative and kAbsolute
//   terms). So nothing comes near 2^1000, and the coordinates are far below TwoSum's 2^1022.
//   Underflow: kAbsolute (2^-1000 per operation, double_word.hpp) bounds the loss; a value
//   too small to be certified against it (a feature of size below about 2^-150 of the largest
//   coordinate, near a root) gives "not certified" and the caller decides exactly.
// t must be a double in [0, 1] (not scaled: it is not a length).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "contact/vec3_ops.hpp"
#include "exactccd/types.hpp"
#include "filter/double_word.hpp"
#include "filter/power_of_two.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/separation_terms.hpp"

namespace exactccd::separation {

/// The sign (-1, 0 meaning "not certified", +1) of feature f's distance polynomial at the
/// double t in [0, 1], for a query's points3 rows `x` (all points at t0, then all at t1) and
/// the minimum distance d; certified whenever nonzero (never for f(t) = 0, an exact zero is
/// left to the caller's exact evaluation). Needs round-to-nearest (double_word.hpp).
/// `approximation`, when given, receives an approximation of f(t) times a positive factor
/// that depends only on x and d (the scaling in the header), for root estimates.
template <std::size_t N>
int certified_distance_sign(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double t,
                            double* approximation = nullptr) {
  using namespace filter::double_word;
  constexpr std::size_t P = N / 2;
  if (!(t >= 0 && t <= 1)) return 0;
  // The largest coordinate magnitude M and the scale 2^s with M 2^s in [1, 2).
  double largest = 0;
  for (const Vec3& p : x) largest = std::fmax(largest, std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))));
  if (!(largest > 0 && largest < 0x1p1023) || !(d >= 0 && d < 0x1p1023)) return 0;  // all zero, or not finite
  // 2^s as two normal double factors (filter::unit_scale), each applied exactly when scaling
  // up: the first product is below 2 (so normal or exact), the second likewise.
  const filter::UnitScale unit = filter::unit_scale(largest);
  const int s = unit.s;  // in (-1023, 1074]
  bool exact = true;
  const auto scale = [&](double v) {
    const double r = unit.apply(v);
    // Scaling down (s < 0): a subnormal result may have lost bits; check by scaling back.
    if (s < 0 && std::fabs(r) < 0x1p-1022 && std::ldexp(r, -s) != v) exact = false;
    return r;
  };
  std::array<Vec3, N> y;
  for (std::size_t i = 0; i < N; ++i) y[i] = {scale(x[i].x), scale(x[i].y), scale(x[i].z)};
  if (!exact) return 0;
  const double sd = unit.apply(d);  // d 2^s, exact when >= 2^-500 (above)
  if (sd > 0x1p400) return 0;
  const Approx dd = sd >= 0x1p-500 ? Approx{{sd, 0.0}, 0.0} * Approx{{sd, 0.0}, 0.0} : Approx{{0.0, 0.0}, 0x1p-1000};
  const auto rel = [&](int i, int j) {
    const Vec3 &u0 = y[static_cast<std::size_t>(i)], &u1 = y[static_cast<std::size_t>(i) + P];
    const Vec3 &v0 = y[static_cast<std::size_t>(j)], &v1 = y[static_cast<std::size_t>(j) + P];
    return Vec3T<Approx>{difference_at(u0.x, v0.x, u1.x, v1.x, t), difference_at(u0.y, v0.y, u1.y, v1.y, t),
                         difference_at(u0.z, v0.z, u1.z, v1.z, t)};
  };
  Approx value{{0.0, 0.0}, 0.0};
  feature_condition(f, rel, dd, [&](const Approx& distance, const auto&...) { value = distance; });
  if (approximation) *approximation = value.value.hi;
  return certain_sign(value);
}

}  // namespace exactccd::separation
