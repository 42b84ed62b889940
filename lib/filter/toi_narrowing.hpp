// Narrowing a time of impact to the tightest double interval (docs/design.md, 5.2, "TOI").
//
// Three steps, cheapest first: certified interval halving of the root's cell (narrow, in the
// interval stage's rounding mode); past kToiHalvings halvings the cell is handed over
// (VolumeRootCell) to toi_in_cell, which picks a double from a long-double Newton guess and
// certifies V's signs at it and its neighbour in double-double arithmetic (volume_sign.hpp),
// with exact GMP signs only where those stay uncertain.
#pragma once

#include <optional>

#include "exactccd/types.hpp"
#include "filter/interval_isolation.hpp"
#include "filter/interval_stage.hpp"

namespace exactccd::filter {

namespace interval {

/// How far narrow() got.
enum class Narrowing {
  done,     ///< lo and hi are consecutive doubles, or the cell became an exact point
  partial,  ///< max_steps halvings done
  stuck,    ///< a midpoint's sign is uncertain; the cell is still valid, just not narrower
};

/// Halves the root cell of p while p's sign at the midpoint is certain, at most max_steps
/// times, until lo and hi are consecutive doubles or the midpoint is an exact zero (the cell
/// becomes that point).
template <int D>
Narrowing narrow(const contact::Poly<Interval, D>& p, RootCell& cell, int max_steps) {
  for (int step = 0; step < max_steps; ++step) {
    if (cell.is_point() || !(next_up_nonnegative(cell.lo) < cell.hi)) return Narrowing::done;
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
  return cell.is_point() || !(next_up_nonnegative(cell.lo) < cell.hi) ? Narrowing::done
                                                                         : Narrowing::partial;
}

}  // namespace interval

/// The tightest double interval around the root of V in `cell` (a cell from the interval stage:
/// see VolumeRootCell), by exact signs of V at dyadic points; nullopt when the exact signs at
/// the cell's ends contradict the cell (then the caller runs the whole stage).
std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const VolumeRootCell& cell);

/// See toi_in_cell(const VertexFaceQuery&, const VolumeRootCell&).
std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const VolumeRootCell& cell);

}  // namespace exactccd::filter
