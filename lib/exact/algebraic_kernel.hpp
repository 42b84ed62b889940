// The pieces of CGAL's univariate algebraic kernel shared by the exact paths (exact_ccd.cpp for
// the contact rule, separation/exact_separation.cpp for minimum separation): integer
// polynomials from rational ones, roots in an interval, and the tightest double enclosure of
// an algebraic time.
#pragma once

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <cstddef>
#include <vector>

#include "contact/polynomial.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact::algebraic {

using Kernel = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using IntegerPoly = Kernel::Polynomial_1;
using Root = Kernel::Algebraic_real_1;
using Bound = Kernel::Bound;

/// The polynomial times the least common multiple of its coefficients' denominators: integer
/// coefficients, the same roots and, the factor being positive, the same signs.
template <int D>
IntegerPoly integer_poly(const contact::Poly<mpq_class, D>& p) {
  mpz_class common = 1;
  for (const mpq_class& x : p.c) mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), x.get_den_mpz_t());
  std::vector<CGAL::Gmpz> coefficients;
  coefficients.reserve(D + 1);
  for (const mpq_class& x : p.c) {
    const mpz_class z = x.get_num() * (common / x.get_den());
    coefficients.emplace_back(z.get_mpz_t());
  }
  return IntegerPoly(coefficients.begin(), coefficients.end());
}

/// The rational x as an algebraic number.
inline Root rational_root(const mpq_class& x) { return Root(Bound(x.get_mpq_t())); }

/// Appends the real roots in [lo, hi] of a polynomial that is not identically zero, sorted and
/// distinct (a nonzero constant has none).
inline void append_roots(const Kernel& kernel, const IntegerPoly& p, const mpq_class& lo, const mpq_class& hi,
                         std::vector<Root>& out) {
  if (CGAL::degree(p) == 0) return;
  kernel.solve_1_object()(p, false, Bound(lo.get_mpq_t()), Bound(hi.get_mpq_t()), std::back_inserter(out));
}

/// Sorts algebraic numbers increasingly and removes repetitions.
void sort_unique(const Kernel& kernel, std::vector<Root>& times);

/// The tightest double interval holding the algebraic number t in [0, 1]: [d, d] when t is the
/// double d, otherwise two consecutive doubles.
TimeInterval enclose(const Kernel& kernel, const Root& t);

/// The most bits of a coefficient of p (bounds CGAL's recursion depth, stack_budget.hpp).
std::size_t coefficient_bits(const IntegerPoly& p);

}  // namespace exactccd::exact::algebraic
