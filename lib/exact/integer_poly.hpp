// Exact univariate polynomials of degree <= 4 with integer coefficients (GMP mpz_class), and
// the few algebraic operations the integer stage needs: exact signs at dyadic points, primitive
// gcds, square-free parts and Bernstein root isolation on [0, 1].
//
// Why not CGAL's Algebraic_kernel_d_1 here: it is the reference and the last fallback, but it
// is generic (any degree, modular gcds, bitstream Descartes) and costs 50-500 us per query on
// the degenerate benchmark data (measured, docs/design.md). The contact polynomials have
// degree <= 4, so the same exact decisions fit in a few hundred GMP operations.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>
#include <vector>

namespace exactccd::exact {

/// p(t) = c[0] + c[1] t + ... + c[deg] t^deg, deg = -1 for the zero polynomial.
struct IntegerPoly {
  std::array<mpz_class, 5> c;
  int deg = -1;

  /// Sets deg to the index of the highest nonzero coefficient.
  void normalize();
  bool is_zero() const { return deg < 0; }
  const mpz_class& leading() const { return c[deg]; }
};

/// A dyadic rational a / 2^k (k >= 0): the exact times the integer stage works with.
struct Dyadic {
  mpz_class a;
  unsigned k = 0;
};

/// Sign of p at a / 2^k, exactly.
int sign_at(const IntegerPoly& p, const Dyadic& x);

/// Sign of p at the double t (every double is a dyadic rational), exactly.
int sign_at(const IntegerPoly& p, double t);

/// The exact dyadic value of a finite double in [0, 1].
Dyadic to_dyadic(double t);

/// p divided by the gcd of its coefficients, with a positive leading coefficient.
IntegerPoly primitive_part(const IntegerPoly& p);

/// The derivative of p.
IntegerPoly derivative(const IntegerPoly& p);

/// gcd(p, q) up to a constant factor, primitive (primitive PRS). Both must be nonzero.
IntegerPoly gcd(const IntegerPoly& p, const IntegerPoly& q);

/// A polynomial with the same real roots as p, all simple: p itself when its discriminant is
/// nonzero, otherwise the primitive part of p / gcd(p, p'). p must be nonzero.
IntegerPoly square_free_part(const IntegerPoly& p);

/// A real root of a square-free polynomial in [0, 1]: either exactly the dyadic `at`, or the
/// only root in the open cell (lo, hi) of dyadic endpoints, where the polynomial has opposite
/// nonzero signs at lo and hi.
struct IsolatedRoot {
  bool exact = false;
  Dyadic at;      // when exact
  Dyadic lo, hi;  // when not exact: lo.k == hi.k, hi.a == lo.a + 1
  int sign_at_lo = 0;
};

/// The real roots in [0, 1] of a nonzero p, in increasing order (Bernstein subdivision with
/// exact integer coefficients; Descartes' rule of signs in the Bernstein basis decides each
/// dyadic cell), or nullopt when a cell deeper than max_depth is undecided (p has a multiple
/// root there, or roots closer than 2^-max_depth). Every root returned is simple.
std::optional<std::vector<IsolatedRoot>> roots_in_unit_interval(const IntegerPoly& p,
                                                                 unsigned max_depth);

/// The roots in [0, 1] of a nonzero polynomial and the polynomial that defines them: p itself
/// when its roots there are simple, else its square-free part.
struct RootsOf {
  IntegerPoly defining;
  std::vector<IsolatedRoot> roots;
};
RootsOf isolate_roots(const IntegerPoly& p);

/// The sign of q on the whole closed cell [lo, lo + 2^-lo.k] when it is constant and nonzero
/// there (certified by the signs of q's Bernstein coefficients on the cell), otherwise 0.
int sign_on_cell(const IntegerPoly& q, const Dyadic& lo);

/// Refines a non-exact root of p with a long-double approximation, checked exactly:
/// - the root becomes exact when it is one of the three doubles nearest to the approximation
///   (queries built from double data often collide at a double time);
/// - otherwise its cell shrinks to width 2^-kRefinedCellBits around the approximation when the
///   exact signs of p at the new ends confirm it (p has one root in the old cell, so the new
///   cell holds the same root).
/// Either way the root is unchanged and certain; only the work of later sign queries drops.
void refine_with_approximation(const IntegerPoly& p, IsolatedRoot& r);

constexpr unsigned kRefinedCellBits = 56;  // long-double guesses of ill-conditioned roots err by ~2^-60

/// A long-double approximation (a guess, to be checked exactly) of the only root in the open
/// interval (lo, hi) of the polynomial c[0] + c[1] t + ... + c[deg] t^deg, whose sign at lo is
/// sign_at_lo and the opposite at hi; safeguarded Newton iteration. Returns a double in
/// [lo, hi].
double approximate_root(const std::array<long double, 5>& c, int deg, double lo, double hi, int sign_at_lo);

/// Halves the cell of a non-exact root once (exact sign of p at the midpoint); the root becomes
/// exact when the midpoint is the root.
void bisect(const IntegerPoly& p, IsolatedRoot& r);

}  // namespace exactccd::exact
