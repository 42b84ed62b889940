// The sign of a feature pair's distance polynomial f (separation_terms.hpp) at a double time t:
// certified in double-double arithmetic (numeric/certified_sign.hpp, the proof there), exact in
// integers where that is not decisive, and a long-double guess of f's root. Used by the
// separation walk's narrowing of a TOI (separation_walk.cpp): at the doubles next to a root of
// f, intervals in doubles cannot give f's sign; double-double almost always can
// (tests/separation/test_distance_sign.cpp counts it), without GMP.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "exactccd/types.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/certified_sign.hpp"
#include "contact/separation_terms.hpp"

namespace exactccd::separation {

/// The sign (-1, 0 meaning "not certified", +1) of feature f's distance polynomial at the
/// double t in [0, 1], for a query's points3 rows `x` (all points at t0, then all at t1) and
/// the minimum distance d; certified whenever nonzero (never for f(t) = 0, an exact zero is
/// left to the caller's exact evaluation). Needs round-to-nearest (double_word.hpp).
/// `approximation`, when given, receives an approximation of f(t) times a positive factor
/// that depends only on x and d (the scaling of numeric/certified_sign.hpp), for root estimates.
template <std::size_t N>
int certified_distance_sign(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double t,
                            double* approximation = nullptr) {
  using Approx = numeric::double_word::Approx;
  const numeric::ScaledRows<N> scaled(x, d);
  const numeric::GeometryAt<N> at(scaled, t);
  if (!at.usable()) return 0;
  Approx value{{0.0, 0.0}, 0.0};
  contact::feature_condition(f, [&](int i, int j) { return at.vector(i, j); }, at.d_squared(),
                    [&](const Approx& distance, const auto&...) { value = distance; });
  if (approximation) *approximation = value.value.hi;
  return numeric::double_word::certain_sign(value);
}

/// The exact sign of feature f's distance polynomial at the double m in (0, 1), in integers:
/// every double is an integer times 2^e; scaling every length (the coordinates and d) by one
/// power of two 2^S multiplies f, homogeneous of degree 2, 4 or 6 in lengths, by a positive
/// factor, so its sign is unchanged. With E the least ulp exponent of the coordinates and d,
/// and m = M 2^-K, the positions at m scaled by 2^(K - E) are the integers X0 2^K + M (X1 - X0).
/// Constant polynomials carry the values (their operators evaluate at once; mpz_class's
/// expression templates would dangle in feature_condition's `auto` temporaries).
template <std::size_t N>
int exact_distance_sign(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double m) {
  constexpr std::size_t P = N / 2;
  using Z = contact::Poly<mpz_class, 0>;
  const auto ulp_exponent = [](double v) {
    int e = 0;
    std::frexp(v, &e);
    return v == 0 ? std::numeric_limits<int>::max() : e - 53;
  };
  int E = ulp_exponent(d);
  for (std::size_t i = 0; i < N; ++i)
    for (const double c : {x[i].x, x[i].y, x[i].z}) E = std::min(E, ulp_exponent(c));
  if (E == std::numeric_limits<int>::max()) E = 0;  // everything is zero
  const auto scaled = [&](double v) {  // v 2^-E, an integer
    if (v == 0) return mpz_class(0);
    int e = 0;
    const double fraction = std::frexp(v, &e);
    mpz_class z(std::ldexp(fraction, 53));  // |fraction| 2^53 < 2^53: exact
    return mpz_class(z << static_cast<mp_bitcnt_t>(e - 53 - E));
  };
  int em = 0;
  const double fm = std::frexp(m, &em);  // m = M 2^-K, K = 53 - em >= 0 for m in (0, 1)
  const mpz_class M(std::ldexp(fm, 53));
  const mp_bitcnt_t K = static_cast<mp_bitcnt_t>(53 - em);
  std::array<Vec3T<Z>, P> exact;
  const auto move_exactly = [&](double x0, double x1) {
    const mpz_class X0 = scaled(x0);
    return Z{{mpz_class((X0 << K) + M * (scaled(x1) - X0))}};
  };
  for (std::size_t p = 0; p < P; ++p)
    exact[p] = {move_exactly(x[p].x, x[p + P].x), move_exactly(x[p].y, x[p + P].y), move_exactly(x[p].z, x[p + P].z)};
  const mpz_class D = scaled(d) << K;
  return sgn(contact::distance_at(f, exact, Z{{mpz_class(D * D)}}).c[0]);
}

/// The exact sign of feature f's distance polynomial at the double m in [0, 1], from the
/// positions at m: certified in double-double arithmetic when that is decisive, else exactly in
/// integers (then `used_integers` is set; a root at a double gives 0). Needs round-to-nearest.
/// `approximation`: as in certified_distance_sign, when the double-double sign decides.
template <std::size_t N>
int distance_sign_at(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double m,
                     double* approximation, bool& used_integers) {
  if (const int s = certified_distance_sign(f, x, d, m, approximation); s != 0) return s;
  used_integers = true;
  return exact_distance_sign(f, x, d, m);
}

/// A guess of the root of feature f's distance in (a, b) (f(a) > 0 > f(b)): the Illinois
/// variant of regula falsi on the distance evaluated from the geometry in long double, until
/// the bracket's ends round to adjacent doubles. Only a guess: the caller certifies signs at
/// whatever it returns.
template <std::size_t N>
double root_guess(const kinds::Feature& f, const std::array<Vec3, N>& x, double d, double a, double b) {
  constexpr std::size_t P = N / 2;
  using L = long double;
  const auto value = [&](L t) {
    std::array<Vec3T<L>, P> at;
    const auto move = [&](double x0, double x1) { return L(x0) + t * (L(x1) - L(x0)); };
    for (std::size_t p = 0; p < P; ++p) at[p] = {move(x[p].x, x[p + P].x), move(x[p].y, x[p + P].y), move(x[p].z, x[p + P].z)};
    return contact::distance_at(f, at, L(d) * L(d));
  };
  L lo = a, hi = b, f_lo = value(lo), f_hi = value(hi);
  if (!(f_lo > 0 && f_hi < 0)) return a + (b - a) / 2;
  int side = 0;
  for (int i = 0; i < 60 && hi - lo > 0; ++i) {
    const L m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(m > lo && m < hi)) break;
    const L fm = value(m);
    if (fm == 0) return static_cast<double>(m);
    if (fm > 0) {
      lo = m;
      f_lo = fm;
      if (side == 1) f_hi /= 2;  // Illinois: halve the stale end
      side = 1;
    } else {
      hi = m;
      f_hi = fm;
      if (side == -1) f_lo /= 2;
      side = -1;
    }
    // Enough for a guess: the root is in [lo, hi], whose ends round to the same or adjacent
    // doubles (the caller examines the guess and its neighbour first).
    const double lo_rounded = static_cast<double>(lo), hi_rounded = static_cast<double>(hi);
    if (hi_rounded <= std::nextafter(lo_rounded, std::numeric_limits<double>::infinity())) break;
  }
  return static_cast<double>((lo + hi) / 2);
}

}  // namespace exactccd::separation
