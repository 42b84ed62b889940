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

/// Halves the root cell of p while p's sign at the midpoint is certain, at most max_steps
/// times, until lo and hi are consecutive doubles or the midpoint is an exact zero (the cell
/// becomes that point).
template <int D>
Narrowing narrow(const contact::Poly<Interval, D>& p, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps; ++step) {
    if (tight(cell)) return Narrowing::done;
    double mid = cell.lo + (cell.hi - cell.lo) / 2;
    if (!(cell.lo < mid && mid < cell.hi)) mid = next_up_nonnegative(cell.lo);
    const SignClass c = classify(p(Interval(mid)));
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
