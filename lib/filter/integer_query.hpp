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

#include "contact/contact_polynomials.hpp"
#include "exact/integer_poly.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filter {

using Integer = mpz_class;

/// The exact kernel's polynomial with the coefficients of p.
template <int D>
exact::IntegerPoly integer_poly(const contact::Poly<Integer, D>& p) {
  exact::IntegerPoly r;
  for (int i = 0; i <= D; ++i) r.c[i] = p.c[i];
  r.normalize();
  return r;
}

/// The query's coordinates times 2^-emin, all integers (see the file comment).
template <class IntegerQuery, class Query>
IntegerQuery to_integer_query(const Query& q) {
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
    Integer z;
    if (x == 0) return z;
    int e = 0;
    const double f = std::frexp(x, &e);
    z = Integer(std::ldexp(f, 53));  // exact: an integer below 2^53 in magnitude
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<unsigned long>(e - 53 - emin));
    return z;
  };
  std::array<Vec3T<Integer>, 8> out;
  for (std::size_t i = 0; i < r.size(); ++i) out[i] = {scaled(r[i].x), scaled(r[i].y), scaled(r[i].z)};
  return from_rows<IntegerQuery>(out);
}

}  // namespace exactccd::filter
