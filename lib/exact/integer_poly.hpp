// Exact univariate polynomials of degree <= 4 with integer coefficients, and
// the few algebraic operations the integer stage needs: exact signs at dyadic points, primitive
// gcds, square-free parts and Bernstein root isolation on [0, 1].
//
// Why not CGAL's Algebraic_kernel_d_1 here: it is the reference and the last fallback, but it
// is generic (any degree, modular gcds, bitstream Descartes) and costs 50-500 us per query on
// the degenerate benchmark data (measured, docs/design.md). The contact polynomials have
// degree <= 4, so the same exact decisions fit in a few hundred GMP operations.
//
// Everything is a template on the integer type Z, instantiated (integer_poly.cpp) for GMP's
// mpz_class and for exact::FixedInteger (integer_ops.hpp: 1024 bits, no allocation, overflow
// throws std::overflow_error). The names without T (IntegerPoly, Dyadic, ...) are the GMP ones.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>
#include <vector>

#include "exact/integer_ops.hpp"

namespace exactccd::exact {

/// p(t) = c[0] + c[1] t + ... + c[deg] t^deg, deg = -1 for the zero polynomial.
template <class Z>
struct IntegerPolyT {
  std::array<Z, 5> c;
  int deg = -1;

  /// Sets deg to the index of the highest nonzero coefficient.
  void normalize() {
    deg = 4;
    while (deg >= 0 && sgn(c[deg]) == 0) --deg;
  }
  bool is_zero() const { return deg < 0; }
  const Z& leading() const { return c[deg]; }
};

/// A dyadic rational a / 2^k (k >= 0): the exact times the integer stage works with.
template <class Z>
struct DyadicT {
  Z a;
  unsigned k = 0;
};

/// Sign of p at a / 2^k, exactly.
template <class Z>
int sign_at(const IntegerPolyT<Z>& p, const DyadicT<Z>& x);

/// Sign of p at the double t (every double is a dyadic rational), exactly.
template <class Z>
int sign_at(const IntegerPolyT<Z>& p, double t);

/// The exact dyadic value of a finite double in [0, 1].
template <class Z = mpz_class>
DyadicT<Z> to_dyadic(double t);

/// p divided by the gcd of its coefficients, with a positive leading coefficient.
template <class Z>
IntegerPolyT<Z> primitive_part(const IntegerPolyT<Z>& p);

/// The derivative of p.
template <class Z>
IntegerPolyT<Z> derivative(const IntegerPolyT<Z>& p);

/// gcd(p, q) up to a constant factor, primitive (primitive PRS). Both must be nonzero.
template <class Z>
IntegerPolyT<Z> gcd(const IntegerPolyT<Z>& p, const IntegerPolyT<Z>& q);

/// A polynomial with the same real roots as p, all simple: p itself when its discriminant is
/// nonzero, otherwise the primitive part of p / gcd(p, p'). p must be nonzero.
template <class Z>
IntegerPolyT<Z> square_free_part(const IntegerPolyT<Z>& p);

/// A real root of a square-free polynomial in [0, 1]: either exactly the dyadic `at`, or the
/// only root in the open cell (lo, hi) of dyadic endpoints, where the polynomial has opposite
/// nonzero signs at lo and hi.
template <class Z>
struct IsolatedRootT {
  bool exact = false;
  DyadicT<Z> at;      // when exact
  DyadicT<Z> lo, hi;  // when not exact: lo.k == hi.k, hi.a == lo.a + 1
  int sign_at_lo = 0;
};

/// The real roots in [0, 1] of a nonzero p, in increasing order (Bernstein subdivision with
/// exact integer coefficients; Descartes' rule of signs in the Bernstein basis decides each
/// dyadic cell), or nullopt when a cell deeper than max_depth is undecided (p has a multiple
/// root there, or roots closer than 2^-max_depth). Every root returned is simple.
template <class Z>
std::optional<std::vector<IsolatedRootT<Z>>> roots_in_unit_interval(const IntegerPolyT<Z>& p, unsigned max_depth);

/// The roots in [0, 1] of a nonzero polynomial and the polynomial that defines them: p itself
/// when its roots there are simple, else its square-free part.
template <class Z>
struct RootsOfT {
  IntegerPolyT<Z> defining;
  std::vector<IsolatedRootT<Z>> roots;
};
template <class Z>
RootsOfT<Z> isolate_roots(const IntegerPolyT<Z>& p);

/// The sign of q on the whole closed cell [lo, lo + 2^-lo.k] when it is constant and nonzero
/// there (certified by the signs of q's Bernstein coefficients on the cell), otherwise 0.
template <class Z>
int sign_on_cell(const IntegerPolyT<Z>& q, const DyadicT<Z>& lo);

/// Refines a non-exact root of p with a long-double approximation, checked exactly:
/// - the root becomes exact when it is one of the three doubles nearest to the approximation
///   (queries built from double data often collide at a double time);
/// - otherwise its cell shrinks to width 2^-kRefinedCellBits around the approximation when the
///   exact signs of p at the new ends confirm it (p has one root in the old cell, so the new
///   cell holds the same root).
/// Either way the root is unchanged and certain; only the work of later sign queries drops.
template <class Z>
void refine_with_approximation(const IntegerPolyT<Z>& p, IsolatedRootT<Z>& r);

constexpr unsigned kRefinedCellBits = 56;  // long-double guesses of ill-conditioned roots err by ~2^-60

/// A long-double approximation (a guess, to be checked exactly) of the only root in the open
/// interval (lo, hi) of the polynomial c[0] + c[1] t + ... + c[deg] t^deg, whose sign at lo is
/// sign_at_lo and the opposite at hi; safeguarded Newton iteration. Returns a double in
/// [lo, hi].
double approximate_root(const std::array<long double, 5>& c, int deg, double lo, double hi, int sign_at_lo);

/// Halves the cell of a non-exact root once (exact sign of p at the midpoint); the root becomes
/// exact when the midpoint is the root.
template <class Z>
void bisect(const IntegerPolyT<Z>& p, IsolatedRootT<Z>& r);

using IntegerPoly = IntegerPolyT<mpz_class>;
using Dyadic = DyadicT<mpz_class>;
using IsolatedRoot = IsolatedRootT<mpz_class>;
using RootsOf = RootsOfT<mpz_class>;

}  // namespace exactccd::exact
