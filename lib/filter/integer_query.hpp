// A double query as an exactly equivalent integer query (docs/design.md, 5.3): every double is
// m 2^e with an integer m, |m| < 2^53; multiplying all 24 coordinates by 2^-emin (emin the
// smallest such e) makes them integers, and the contact polynomials of the scaled query are the
// true ones times positive powers of two: every sign, root and decision is unchanged.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <type_traits>
#include <utility>

#include "contact/contact_polynomials.hpp"
#include "exact/integer_poly.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filter {

using Integer = mpz_class;

/// The exact kernel's polynomial with the coefficients of p (Z: mpz_class or exact::FixedInteger).
template <int D, class Z>
exact::IntegerPolyT<Z> integer_poly(const contact::Poly<Z, D>& p) {
  exact::IntegerPolyT<Z> r;
  for (int i = 0; i <= D; ++i) r.c[i] = p.c[i];
  r.normalize();
  return r;
}

/// The spread emax - emin of the exponents e of the query's nonzero coordinates written as
/// m 2^e with |m| < 2^53 (0 when at most one exponent occurs): after to_integer_query every
/// coordinate is an integer below 2^(53 + spread) in magnitude.
template <class Query>
int exponent_spread(const Query& q) {
  int emin = INT_MAX, emax = INT_MIN;
  for (const Vec3& v : rows(q))
    for (double x : {v.x, v.y, v.z})
      if (x != 0) {
        int e = 0;
        std::frexp(x, &e);
        emin = std::min(emin, e);
        emax = std::max(emax, e);
      }
  return emin == INT_MAX ? 0 : emax - emin;
}

/// The query's coordinates times 2^-emin, all integers (see the file comment), in the integer
/// type of IntegerQuery (mpz_class or exact::FixedInteger; the latter throws std::overflow_error
/// when a coordinate does not fit).
template <class IntegerQuery, class Query>
IntegerQuery to_integer_query(const Query& q) {
  using Z = std::decay_t<decltype(rows(std::declval<const IntegerQuery&>())[0].x)>;
  const auto r = rows(q);
  int emin = INT_MAX;
  for (const Vec3& v : r)
    for (double x : {v.x, v.y, v.z})
      if (x != 0) {
        int e = 0;
        std::frexp(x, &e);
        emin = std::min(emin, e - 53);
      }
  const auto scaled = [emin](double x) {
    Z z(0);
    if (x == 0) return z;
    int e = 0;
    const double f = std::frexp(x, &e);
    z = Z(static_cast<long>(std::ldexp(f, 53)));  // exact: an integer below 2^53 in magnitude
    return exact::shifted(z, static_cast<unsigned long>(e - 53 - emin));
  };
  std::array<Vec3T<Z>, 8> out;
  for (std::size_t i = 0; i < r.size(); ++i) out[i] = {scaled(r[i].x), scaled(r[i].y), scaled(r[i].z)};
  return from_rows<IntegerQuery>(out);
}

}  // namespace exactccd::filter
