// The two exact integer types of the integer stages and the few operations the generic code of
// integer_poly.cpp and integer_stage.cpp needs beyond + - * and comparisons, one overload per
// type:
// - mpz_class (GMP): unbounded, allocates for every temporary;
// - FixedInteger: Boost.Multiprecision's fixed-width 1024-bit signed-magnitude cpp_int, stored
//   inline (no allocation) and *checked*: every operation whose exact result does not fit
//   (|x| >= 2^1024) throws std::overflow_error instead of wrapping, and a bitwise operation on
//   a negative value throws std::range_error (the helpers below shift magnitudes only). Both
//   derive from std::runtime_error. So a computation in FixedInteger either returns the exact
//   result or throws: the fixed stage (filter/integer_stage.hpp, fixed_integer_stage) catches that and hands
//   the query to the GMP stage. Its bit bound says when no throw can happen on its common path.
#pragma once

#include <gmpxx.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace exactccd::exact {

inline constexpr unsigned kFixedIntegerBits = 1024;

/// A 1024-bit integer without allocation; overflow throws (see the file comment).
using FixedInteger = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<kFixedIntegerBits, kFixedIntegerBits, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::checked, void>,
    boost::multiprecision::et_off>;

/// -1, 0 or +1.
inline int sgn(const mpz_class& x) { return mpz_sgn(x.get_mpz_t()); }
inline int sgn(const FixedInteger& x) { return x.sign(); }

/// x 2^e.
inline mpz_class shifted(const mpz_class& x, unsigned long e) {
  mpz_class r;
  mpz_mul_2exp(r.get_mpz_t(), x.get_mpz_t(), e);
  return r;
}
inline FixedInteger shifted(const FixedInteger& x, unsigned long e) {
  if (x.sign() >= 0) return x << e;  // checked: throws when a set bit would be lost
  return -(FixedInteger(-x) << e);
}

/// x / d for d dividing x exactly.
inline void divide_exactly(mpz_class& x, const mpz_class& d) { mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), d.get_mpz_t()); }
inline void divide_exactly(FixedInteger& x, const FixedInteger& d) { x /= d; }

/// gcd(|a|, |b|) (0 when both are 0).
inline mpz_class gcd_of(const mpz_class& a, const mpz_class& b) {
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return g;
}
inline FixedInteger gcd_of(const FixedInteger& a, const FixedInteger& b) {
  return boost::multiprecision::gcd(abs(a), abs(b));
}

/// The number of bits of |x| (1 for x = 0, as mpz_sizeinbase).
inline long bit_length(const mpz_class& x) { return static_cast<long>(mpz_sizeinbase(x.get_mpz_t(), 2)); }
inline long bit_length(const FixedInteger& x) {
  return x.sign() == 0 ? 1 : static_cast<long>(boost::multiprecision::msb(abs(x))) + 1;
}

/// The leading (at most 64) bits of x as a signed long double, and the power of two `shift`
/// with x ~ result 2^shift (truncated towards zero; a guess's input only).
inline long double leading_bits(const mpz_class& x, long& shift) {
  shift = std::max(bit_length(x) - 64, 0L);
  mpz_class t;
  mpz_tdiv_q_2exp(t.get_mpz_t(), x.get_mpz_t(), static_cast<unsigned long>(shift));
  mpz_class magnitude = abs(t);
  return static_cast<long double>(mpz_get_ui(magnitude.get_mpz_t())) * sgn(t);
}
inline long double leading_bits(const FixedInteger& x, long& shift) {
  shift = std::max(bit_length(x) - 64, 0L);
  const FixedInteger magnitude = abs(x) >> static_cast<unsigned>(shift);
  return static_cast<long double>(static_cast<std::uint64_t>(magnitude)) * x.sign();
}

/// For 0 <= a: a truncated to its leading 53 bits, as m 2^x with m in [0.5, 1) (or m = 0), like
/// mpz_get_d_2exp; m is exact (at most 53 bits).
inline double truncated_mantissa(const mpz_class& a, long& x) { return mpz_get_d_2exp(&x, a.get_mpz_t()); }
inline double truncated_mantissa(const FixedInteger& a, long& x) {
  if (a.sign() == 0) {
    x = 0;
    return 0.0;
  }
  const long bits = bit_length(a);
  x = bits;
  const FixedInteger top = bits > 53 ? FixedInteger(a >> static_cast<unsigned>(bits - 53)) : FixedInteger(a << static_cast<unsigned>(53 - bits));
  return std::ldexp(static_cast<double>(static_cast<std::uint64_t>(top)), -53);  // exact: 53 bits
}

/// The largest double <= a / 2^k for 0 <= a (a time in [0, 1]); `exact` tells whether it equals
/// a / 2^k. The GMP version is exact for every value (mpq_get_d truncates); the fixed version
/// throws std::overflow_error (the query goes to the GMP stage) when the value is below 2^-1022,
/// where the truncated double would be subnormal and need care this path does not take.
inline double floor_to_double(const mpz_class& a, unsigned k, bool& exact) {
  mpq_class x(a);
  mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), k);
  const double d = x.get_d();  // truncation: rounds down for x >= 0
  exact = mpq_class(d) == x;
  return d;
}
inline double floor_to_double(const FixedInteger& a, unsigned k, bool& exact) {
  if (a.sign() == 0) {
    exact = true;
    return 0.0;
  }
  const long bits = bit_length(a);
  if (bits - static_cast<long>(k) - 1 < -1022) throw std::overflow_error("fixed integer: subnormal time");
  const unsigned drop = bits > 53 ? static_cast<unsigned>(bits - 53) : 0u;
  const FixedInteger top = a >> drop;
  exact = (top << drop) == a;
  // top < 2^53 and top 2^(drop - k) >= 2^-1022: a normal double, exactly.
  return std::ldexp(static_cast<double>(static_cast<std::uint64_t>(top)), static_cast<int>(drop) - static_cast<int>(k));
}

}  // namespace exactccd::exact
