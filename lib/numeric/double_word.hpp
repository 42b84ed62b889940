// Double-double ("double-word") arithmetic with a running error bound: a certified sign of a
// polynomial expression in doubles, far more often decisive than intervals in doubles (about
// 106 bits instead of 53). Used by certified_volume_sign (volume_sign.cpp) and by the
// minimum-separation distance sign (separation/distance_sign.hpp).
//
// After Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic building blocks
// of double-word arithmetic", ACM TOMS 44(2), 2017 (JMP17). Needs round-to-nearest and a
// correctly rounded std::fma (IEEE 754 fusedMultiplyAdd); the project compiles with
// -ffp-contract=off, so no other expression is fused. u = 2^-53. Proven relative error bounds,
// in the absence of underflow and overflow:
//   add (AccurateDWPlusDW, JMP17 Algorithm 6):      3u^2 / (1 - 4u)
//   mul by a double (DWTimesFP3, Algorithm 9):      2u^2
//   mul (DWTimesDW3, Algorithm 12):                 4u^2 (5u^2 for Algorithm 11)
// kRelative = 16u^2 = 2^-102 bounds every one of them with a margin of 3x.
// Underflow: every operation below is a handful of elementary ones, each losing at most
// 2^-1075 absolutely when its result is subnormal (additions are then exact); kAbsolute =
// 2^-1000 per double-double operation bounds that loss with a huge margin (and is itself far
// below any value the callers certify). Overflow: the callers bound their inputs so that every
// value and every error bound stays below 2^1000 (see each caller).
#pragma once

#include <cmath>

namespace exactccd::numeric::double_word {

constexpr double kRelative = 0x1p-102;
constexpr double kAbsolute = 0x1p-1000;

/// hi + lo, |lo| <= ulp(hi) / 2 (after normalisation).
struct DD {
  double hi, lo;
};

/// a + b = s + e exactly (Knuth's TwoSum).
inline DD two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

/// a + b = s + e exactly when |a| >= |b| or a == 0 (Dekker's FastTwoSum).
inline DD fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a b = p + e exactly (barring underflow), with FMA.
inline DD two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// x + y, JMP17 Algorithm 6.
inline DD add(const DD& x, const DD& y) {
  const DD s = two_sum(x.hi, y.hi);
  const DD t = two_sum(x.lo, y.lo);
  const DD v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}

/// x y for a double y, JMP17 Algorithm 9.
inline DD mul(const DD& x, double y) {
  const DD c = two_prod(x.hi, y);
  return fast_two_sum(c.hi, std::fma(x.lo, y, c.lo));
}

/// x y, JMP17 Algorithm 12.
inline DD mul(const DD& x, const DD& y) {
  const DD c = two_prod(x.hi, y.hi);
  const double tl1 = std::fma(x.hi, y.lo, x.lo * y.lo);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  return fast_two_sum(c.hi, c.lo + cl2);
}

/// -x (exact).
inline DD neg(const DD& x) { return {-x.hi, -x.lo}; }

/// |hi| + |lo| >= |hi + lo|.
inline double magnitude(const DD& x) { return std::fabs(x.hi) + std::fabs(x.lo); }

/// A double-double value and a bound on its distance to the exact quantity it stands for.
struct Approx {
  DD value;
  double error;
};

// Error propagation (x~, y~ the computed operands, x, y the exact ones, e_x, e_y their bounds):
//   sum:     |z~ - (x + y)| <= |z~ - (x~ + y~)| + e_x + e_y, and |z~ - (x~ + y~)| <= k |z~|
//            up to a factor 1 / (1 - k) absorbed by the margin of kRelative;
//   product: |x~ y~ - x y| <= |x~| e_y + |y~| e_x + e_x e_y, plus the rounding k |z~|.
// The bounds themselves are computed in double with round-to-nearest: fewer than 10 roundings
// each, of nonnegative quantities, so an expression of depth n has its bound computed with a
// relative error below 10 n u; certain_sign asks for a margin of 2x (n < 10^14).

/// x + y with its error bound.
inline Approx operator+(const Approx& x, const Approx& y) {
  const DD z = add(x.value, y.value);
  return {z, x.error + y.error + kRelative * magnitude(z) + kAbsolute};
}

/// x - y with its error bound.
inline Approx operator-(const Approx& x, const Approx& y) { return x + Approx{neg(y.value), y.error}; }

/// x y with its error bound.
inline Approx operator*(const Approx& x, const Approx& y) {
  const DD z = mul(x.value, y.value);
  return {z, magnitude(x.value) * y.error + magnitude(y.value) * x.error + x.error * y.error +
                 kRelative * magnitude(z) + kAbsolute};
}

/// x t for an exact double t, with its error bound.
inline Approx scaled(const Approx& x, double t) {
  const DD z = mul(x.value, t);
  return {z, std::fabs(t) * x.error + kRelative * magnitude(z) + kAbsolute};
}

/// A coordinate difference v - u moving linearly over the step: its parts that do not depend
/// on t, formed once (moving_difference), and its value at a time t (at).
struct MovingDifference {
  Approx start;   ///< v0 - u0, exactly (TwoSum)
  Approx change;  ///< (v1 - u1) - (v0 - u0), with its error bound

  /// The value at time t: (v0 - u0) + t ((v1 - u1) - (v0 - u0)), as relative_motion in
  /// contact_polynomials.hpp.
  Approx at(double t) const { return start + scaled(change, t); }
};

/// The difference v - u whose values at t0 and t1 are v0 - u0 and v1 - u1, each exact
/// (TwoSum: no overflow when the inputs are below 2^1022 in magnitude).
inline MovingDifference moving_difference(double u0, double v0, double u1, double v1) {
  const Approx d0{two_sum(v0, -u0), 0.0};
  const Approx d1{two_sum(v1, -u1), 0.0};
  return {d0, d1 - d0};
}

/// The difference v - u at time t (moving_difference, at): for a single t.
inline Approx difference_at(double u0, double v0, double u1, double v1, double t) {
  return moving_difference(u0, v0, u1, v1).at(t);
}

/// The certified sign (-1 or 1) of the exact quantity v stands for, or 0 when the bound does
/// not exclude zero (including an exact zero, and an overflowed bound). value = fl(hi + lo)
/// has the sign of hi + lo and |value| (1 - 2^-50) <= |hi + lo|; the factor 2 covers the
/// rounding of the bound itself (above).
inline int certain_sign(const Approx& v) {
  const double value = v.value.hi + v.value.lo;
  if (std::fabs(value) * (1 - 0x1p-50) > 2 * v.error) return value > 0 ? 1 : -1;
  return 0;
}

}  // namespace exactccd::numeric::double_word
