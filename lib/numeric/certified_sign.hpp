// The certified sign of a geometric expression of a query's points at a double time t, in
// double-double arithmetic (double_word.hpp) with a running error bound, without GMP. Used to
// narrow times of impact to adjacent doubles: at the doubles next to a root, intervals in
// doubles cannot give the sign (the value is about 2^-53 of its terms), double-double almost
// always can; the callers decide exactly in integers only where it cannot. The expressions:
// the contact volume V (filter/toi_narrowing.cpp) and the minimum-separation distance f of a
// feature pair (separation/separation_walk.cpp).
//
// Evaluated from the geometry at t, never from power-basis coefficients: the vector from point
// i to point j at t is (v0 - u0) + t ((v1 - u1) - (v0 - u0)), the two differences at t0 and t1
// exact (TwoSum), so the error bound is relative to the primitives' local size, not to the
// coordinates' or the coefficients'.
//
// Scaling: every expression evaluated is homogeneous in lengths (V of degree 3; f of degree 2,
// 4 or 6, d counted as a length), so multiplying every coordinate and d by 2^s multiplies it by
// 2^(k s): a positive factor, the sign is unchanged. Every input is first scaled by the power of
// two 2^s that brings the largest coordinate magnitude M into [1, 2). A product by a power of two
// is exact when its result is representable without rounding: scaling up (s > 0) never
// overflows (the coordinates become below 2) and never creates bits below 2^-1074, so it is
// exact (two factors when 2^s is not a double); scaling down (s < 0) is exact unless the result
// is subnormal, and such a coordinate is scaled back and compared: an inexact one makes the
// geometry unusable ("not certified"). d is scaled likewise: when d 2^s >= 2^-500 it is normal,
// so exact; when d 2^s > 2^400 the geometry is unusable; when d 2^s < 2^-500 (d negligible
// against the coordinates) its square is not formed: d^2 2^(2s) is in [0, 2^-1000], represented
// by the value 0 with the error bound 2^-1000 (a valid Approx whatever the rounding of d 2^s:
// rounding is monotone). So:
//   Overflow: every scaled coordinate is below 2 in magnitude; every difference at t0 or t1
//   below 4, the difference of those below 8, the value at t in [0, 1] below 12 < 2^4 (error
//   bounds far smaller). The largest expressions are of degree 6: edge-edge w = da x db has
//   components below 2 * 2^8 = 2^9, h = w.r below 3 * 2^13 < 2^15, h^2 below 2^30;
//   s = (r x db).w and u below 3 * 2^9 * 2^9 < 2^20, |w|^2 below 2^20; d^2 <= 2^800, so
//   d^2 |w|^2 below 2^820; point-triangle likewise (n = e1 x e2 below 2^9, n.(p - a) below
//   2^15); V below 6 * 2^12 < 2^15; point-edge and point-point smaller. Error bounds are of the
//   same order (each a sum of products of magnitudes and bounds of the operands, plus kRelative
//   and kAbsolute terms). So nothing comes near 2^1000, and the coordinates are far below
//   TwoSum's 2^1022.
//   Underflow: kAbsolute (2^-1000 per operation, double_word.hpp) bounds the loss; a value too
//   small to be certified against it (a feature of size below about 2^-150 of the largest
//   coordinate, near a root) is not certified and the caller decides exactly.
// t must be a double in [0, 1] (it is not scaled: it is not a length). Needs round-to-nearest
// (double_word.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "exactccd/types.hpp"
#include "numeric/double_word.hpp"
#include "numeric/power_of_two.hpp"

namespace exactccd::numeric {

/// A query's points scaled exactly as in the header (the power of two of its largest
/// coordinate), and d^2 likewise: what every time t of one query shares (scaled once, then
/// evaluated at any number of times by GeometryAt). N rows: the P = N / 2 points at t0, then the
/// same points at t1.
template <std::size_t N>
class ScaledRows {
 public:
  using Approx = double_word::Approx;  ///< a double-double value with its error bound

  /// The points of `x` (finite doubles) and the length d >= 0.
  explicit ScaledRows(const std::array<Vec3, N>& x, double d = 0) {
    // The largest magnitude by plain comparisons (an infinity makes it infinite and the rows
    // unusable below; a NaN is skipped here and makes every value NaN, never certified).
    double largest = 0;
    for (const Vec3& p : x)
      for (const double v : {p.x, p.y, p.z}) largest = std::fabs(v) > largest ? std::fabs(v) : largest;
    if (!(largest > 0 && largest < 0x1p1023) || !(d >= 0 && d < 0x1p1023)) return;  // all zero, or not finite
    // 2^s as two normal double factors (unit_scale), each applied exactly when scaling up: the
    // first product is below 2 (so normal or exact), the second likewise.
    const UnitScale unit = unit_scale(largest);
    bool exact = true;
    const auto scale = [&](double v) {
      const double r = unit.apply(v);
      // Scaling down (s < 0): a subnormal result may have lost bits; check by scaling back.
      if (unit.s < 0 && std::fabs(r) < 0x1p-1022 && std::ldexp(r, -unit.s) != v) exact = false;
      return r;
    };
    for (std::size_t i = 0; i < N; ++i) y_[i] = {scale(x[i].x), scale(x[i].y), scale(x[i].z)};
    const double sd = unit.apply(d);  // d 2^s, exact when >= 2^-500 (header)
    if (!exact || sd > 0x1p400) return;
    d_squared_ = sd >= 0x1p-500 ? Approx{{sd, 0.0}, 0.0} * Approx{{sd, 0.0}, 0.0} : Approx{{0.0, 0.0}, 0x1p-1000};
    usable_ = true;
  }

  /// False when nothing can be certified (every coordinate zero, an inexact scaling, d beyond
  /// the range of the header).
  bool usable() const { return usable_; }
  /// The scaled rows.
  const std::array<Vec3, N>& rows() const { return y_; }
  /// d^2, scaled as the coordinates.
  const Approx& d_squared() const { return d_squared_; }

 private:
  std::array<Vec3, N> y_{};
  Approx d_squared_{{0.0, 0.0}, 0.0};
  bool usable_ = false;
};

/// A query's points at one double time t, in double-double, from its scaled rows (ScaledRows,
/// which must outlive this object).
/// The vector from point i to point j of scaled rows (the points at t0, then at t1), moving
/// linearly over the step: its parts that do not depend on t, formed once
/// (double_word::MovingDifference), for a caller that evaluates it at many t.
template <std::size_t N>
Vec3T<double_word::MovingDifference> moving_vector(const ScaledRows<N>& scaled, int i, int j) {
  constexpr std::size_t P = N / 2;
  const std::array<Vec3, N>& y = scaled.rows();
  const Vec3 &u0 = y[static_cast<std::size_t>(i)], &u1 = y[static_cast<std::size_t>(i) + P];
  const Vec3 &v0 = y[static_cast<std::size_t>(j)], &v1 = y[static_cast<std::size_t>(j) + P];
  using double_word::moving_difference;
  return {moving_difference(u0.x, v0.x, u1.x, v1.x), moving_difference(u0.y, v0.y, u1.y, v1.y),
          moving_difference(u0.z, v0.z, u1.z, v1.z)};
}

/// A moving vector (moving_vector) at time t.
inline Vec3T<double_word::Approx> vector_at(const Vec3T<double_word::MovingDifference>& v, double t) {
  return {v.x.at(t), v.y.at(t), v.z.at(t)};
}

template <std::size_t N>
class GeometryAt {
 public:
  using Approx = double_word::Approx;  ///< a double-double value with its error bound

  /// The scaled points at t.
  GeometryAt(const ScaledRows<N>& scaled, double t) : scaled_(scaled), t_(t) {}
  GeometryAt(ScaledRows<N>&&, double) = delete;  ///< not from a temporary

  /// False when nothing can be certified (t outside [0, 1], or the rows unusable).
  bool usable() const { return t_ >= 0 && t_ <= 1 && scaled_.usable(); }

  /// The vector from point i to point j at t.
  Vec3T<Approx> vector(int i, int j) const { return vector_at(moving_vector(scaled_, i, j), t_); }

  /// d^2, scaled as the coordinates.
  const Approx& d_squared() const { return scaled_.d_squared(); }

 private:
  const ScaledRows<N>& scaled_;
  double t_;
};

}  // namespace exactccd::numeric
