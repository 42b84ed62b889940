// Narrowing a root cell of a polynomial by certified interval halving (docs/design.md, 5.2,
// "TOI"): each halving keeps the half where the sign changes, as long as the sign at the
// midpoint is certain; an exact zero there makes the cell that point.
#pragma once

#include "contact/polynomial.hpp"
#include "filter/interval/isolation.hpp"

namespace exactccd::filter::interval {

/// How far narrow() got.
enum class Narrowing {
  done,     ///< lo and hi are consecutive doubles, or the cell became an exact point
  partial,  ///< max_steps halvings done
  stuck,    ///< a midpoint's sign is uncertain; the cell is still valid, just not narrower
};

/// True when the cell cannot be narrowed any further (a point, or consecutive doubles).
inline bool tight(const RootCell& cell) { return cell.is_point() || !(next_up_nonnegative(cell.lo) < cell.hi); }

/// The sign class (classify) of p's interval value at a double t > 0, under the stage's upward
/// rounding: Horner's scheme on the bounds. Write the interval [lo, hi] as the pair (-lo, hi),
/// as CGAL::Interval_nt does. For t > 0 the product of [lo, hi] by t is [lo t, hi t], and every
/// step r t + c of Horner's scheme is increasing in each bound, so rounding upwards gives
///     hi' = fl(fl(hi t) + c.hi) >= hi t + c.hi,   nlo' = fl(fl(nlo t) + (-c.lo)) >= -(lo t + c.lo)
/// with nlo = -lo: the interval [-nlo', hi'] holds r t + c for every r in [lo, hi] and c in
/// [c.lo, c.hi], so by induction p(t) lies in [-nlo, hi] at the end. These are, bit for bit,
/// the bounds CGAL's interval-by-double product and sum compute (the same two products and sums
/// rounded upwards; its product also takes the minimum with the widest interval, which only
/// replaces a NaN from 0 times an infinite bound: t > 0 gives none), without its per-operation
/// compiler barriers and that minimum on the loop's critical path. Infinite bounds (overflow)
/// stay infinite and never classify as certain. Two independent chains of D multiplications
/// and additions: no rounding-mode switch, no allocation.
template <int D>
SignClass sign_class_at(const contact::Poly<Interval, D>& p, double t) {
  double nlo = -p.c[D].inf(), hi = p.c[D].sup();
  for (int k = D - 1; k >= 0; --k) {
    nlo = nlo * t + -p.c[k].inf();  // -p.c[k].inf() is exact
    hi = hi * t + p.c[k].sup();
  }
  if (nlo < 0) return SignClass::positive;  // lower bound -nlo > 0
  if (hi < 0) return SignClass::negative;
  if (nlo == 0 && hi == 0) return SignClass::zero;
  return SignClass::unknown;
}

/// Halves the root cell of p while p's sign at the midpoint is certain, at most max_steps
/// times, until lo and hi are consecutive doubles or the midpoint is an exact zero (the cell
/// becomes that point).
template <int D>
Narrowing narrow(const contact::Poly<Interval, D>& p, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps; ++step) {
    if (tight(cell)) return Narrowing::done;
    double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) mid = next_up_nonnegative(cell.lo);
    const SignClass c = sign_class_at(p, mid);  // mid in (lo, hi), lo >= 0: mid > 0
    if (c == SignClass::unknown) return Narrowing::stuck;
    if (c == SignClass::zero) {
      cell = RootCell{mid, mid, 0};
      return Narrowing::done;
    }
    const int s = c == SignClass::positive ? 1 : -1;
    (s == cell.sign_at_lo ? cell.lo : cell.hi) = mid;
  }
  return tight(cell) ? Narrowing::done : Narrowing::partial;
}

/// Narrows the cell (as narrow) and tells whether it changed.
template <int D>
bool narrowed(const contact::Poly<Interval, D>& p, RootCell& cell, int max_steps) {
  const RootCell before = cell;
  narrow(p, cell, max_steps);
  return cell.lo != before.lo || cell.hi != before.hi;
}

}  // namespace exactccd::filter::interval
