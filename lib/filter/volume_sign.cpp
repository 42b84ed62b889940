#include "filter/volume_sign.hpp"

#include <array>
#include <cmath>

#include "contact/contact_rule.hpp"

namespace exactccd::filter {
namespace {

// Double-double ("double-word") arithmetic, round-to-nearest, with FMA, after Joldes, Muller
// and Popescu, "Tight and rigorous error bounds for basic building blocks of double-word
// arithmetic", ACM TOMS 44(2), 2017 (JMP17). u = 2^-53. Proven relative error bounds, in the
// absence of underflow and overflow:
//   add (AccurateDWPlusDW, JMP17 Algorithm 6):      3u^2 / (1 - 4u)
//   mul by a double (DWTimesFP3, Algorithm 9):      2u^2
//   mul (DWTimesDW3, Algorithm 12):                 4u^2 (5u^2 for Algorithm 11)
// kRelative = 16u^2 = 2^-102 bounds every one of them with a margin of 3x.
constexpr double kRelative = 0x1p-102;
// Underflow: every operation below is a handful of elementary ones, each losing at most
// 2^-1075 absolutely when its result is subnormal; 2^-1000 per double-double operation bounds
// that loss with a huge margin (and is itself far below any V the filter can certify).
constexpr double kAbsolute = 0x1p-1000;

struct DD {
  double hi, lo;
};

/// a + b = s + e exactly (Knuth's TwoSum).
DD two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

/// a + b = s + e exactly when |a| >= |b| or a == 0 (Dekker's FastTwoSum).
DD fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a b = p + e exactly (barring underflow), with FMA.
DD two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

DD add(const DD& x, const DD& y) {  // JMP17 Algorithm 6
  const DD s = two_sum(x.hi, y.hi);
  const DD t = two_sum(x.lo, y.lo);
  const DD v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}

DD mul(const DD& x, double y) {  // JMP17 Algorithm 9
  const DD c = two_prod(x.hi, y);
  return fast_two_sum(c.hi, std::fma(x.lo, y, c.lo));
}

DD mul(const DD& x, const DD& y) {  // JMP17 Algorithm 12
  const DD c = two_prod(x.hi, y.hi);
  const double tl1 = std::fma(x.hi, y.lo, x.lo * y.lo);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  return fast_two_sum(c.hi, c.lo + cl2);
}

DD neg(const DD& x) { return {-x.hi, -x.lo}; }

double magnitude(const DD& x) { return std::fabs(x.hi) + std::fabs(x.lo); }  // >= |hi + lo|

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
// each, so their relative error is below 10u; the final test asks for a margin of 2x.
Approx operator+(const Approx& x, const Approx& y) {
  const DD z = add(x.value, y.value);
  return {z, x.error + y.error + kRelative * magnitude(z) + kAbsolute};
}

Approx operator-(const Approx& x, const Approx& y) { return x + Approx{neg(y.value), y.error}; }

Approx operator*(const Approx& x, const Approx& y) {
  const DD z = mul(x.value, y.value);
  return {z, magnitude(x.value) * y.error + magnitude(y.value) * x.error + x.error * y.error +
                 kRelative * magnitude(z) + kAbsolute};
}

Approx scaled(const Approx& x, double t) {  // t exact
  const DD z = mul(x.value, t);
  return {z, std::fabs(t) * x.error + kRelative * magnitude(z) + kAbsolute};
}

/// A coordinate difference v - u at t0 and at t1 exactly, and its value at time t:
/// (v0 - u0) + t ((v1 - u1) - (v0 - u0)), as relative_motion in contact_polynomials.hpp.
Approx difference_at(double u0, double v0, double u1, double v1, double t) {
  const Approx d0{two_sum(v0, -u0), 0.0};  // exact (no overflow: |inputs| <= 2^500)
  const Approx d1{two_sum(v1, -u1), 0.0};
  return d0 + scaled(d1 - d0, t);
}

using Rows = std::array<Vec3, 8>;

/// The vector from row `from` to row `to` at time t (t1 rows are four rows later).
std::array<Approx, 3> vector_at(const Rows& r, int from, int to, double t) {
  const Vec3 &u0 = r[from], &u1 = r[from + 4], &v0 = r[to], &v1 = r[to + 4];
  return {difference_at(u0.x, v0.x, u1.x, v1.x, t), difference_at(u0.y, v0.y, u1.y, v1.y, t),
          difference_at(u0.z, v0.z, u1.z, v1.z, t)};
}

/// sign(A . (B x C)) at time t for the vectors from row `o` to rows `a`, `b`, `c`.
int volume_sign(const Rows& r, int o, int a, int b, int c, double t) {
  if (!(t >= 0 && t <= 1)) return contact::kUnknownSign;
  // No overflow: with |coordinates| <= 2^300 every difference and its value at t is below
  // 2^302 and every product of three, and sum of such, below 2^910 (errors likewise).
  // Underflow is covered by kAbsolute.
  for (const Vec3& p : r)
    for (double x : {p.x, p.y, p.z})
      if (!(std::fabs(x) <= 0x1p300)) return contact::kUnknownSign;
  const auto A = vector_at(r, o, a, t), B = vector_at(r, o, b, t), C = vector_at(r, o, c, t);
  const Approx v = A[0] * (B[1] * C[2] - B[2] * C[1]) + A[1] * (B[2] * C[0] - B[0] * C[2]) +
                   A[2] * (B[0] * C[1] - B[1] * C[0]);
  const double value = v.value.hi + v.value.lo;  // the rounded value: same sign as hi + lo
  if (std::fabs(value) * (1 - 0x1p-50) > 2 * v.error) return value > 0 ? 1 : -1;
  return contact::kUnknownSign;  // including V(t) = 0 exactly: the caller decides exactly
}

}  // namespace

// V = (b - a) . ((c - a) x (p - a)): rows p = 0, a = 1, b = 2, c = 3.
int certified_volume_sign(const VertexFaceQuery& q, double t) { return volume_sign(rows(q), 1, 2, 3, 0, t); }

// V = (a1 - a0) . ((b0 - a0) x (b1 - a0)): rows a0 = 0, a1 = 1, b0 = 2, b1 = 3.
int certified_volume_sign(const EdgeEdgeQuery& q, double t) { return volume_sign(rows(q), 0, 1, 2, 3, t); }

}  // namespace exactccd::filter
