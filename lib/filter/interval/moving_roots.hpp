// The interval stage when the volume V is not identically zero (docs/design.md, 5.2): contact
// needs V(t) = 0, so the candidates are V's roots in [0, 1], isolated in increasing order; the
// first root where the in-plane rule holds is the TOI.
#pragma once

#include <optional>

#include "filter/interval/in_plane_over_cell.hpp"
#include "filter/interval/isolation.hpp"
#include "filter/root_cells.hpp"
#include "filter/interval/narrowing.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter::interval {

/// The verdict at one root cell of V; at t = 0 and t = 1 the configuration is static, and where
/// intervals are uncertain there `ends` gives the exact contact (CGAL's static predicates).
template <class Polys, class Ends>
contact::Truth verdict_at_root(const Polys& P, const Ends& ends, RootCell& cell) {
  const contact::Truth v = in_plane_verdict(P, P.volume(), false, cell);
  if (v == contact::Truth::unknown && cell.is_point() && (cell.lo == 0.0 || cell.lo == 1.0))
    return contact::truth(ends.contact(cell.lo == 0.0 ? 0 : 1));
  return v;
}

/// The roots of V in increasing order (`ends.volume_sign(e)`: V's exact sign at t = e where
/// intervals are uncertain). A collision's TOI is certified when the root is narrowed to
/// adjacent doubles; when only its cell is known it is handed over in `toi_cell` (a later
/// stage narrows it exactly); it is the TOI only if no earlier root is undecided.
template <class Polys, class Ends>
pipeline::Outcome moving_strategy(const Polys& P, const Ends& ends, bool want_toi,
                                  std::optional<VolumeRootCell>& toi_cell) {
  RootCells cells;
  if (isolate_roots(P.volume(), cells, true, [&](int end) { return ends.volume_sign(end); }) == Isolation::failed ||
      cells.size() > 3)
    return pipeline::Outcome::undecided();
  bool earlier_undecided = false;
  for (RootCell cell : cells) {
    const contact::Truth v = verdict_at_root(P, ends, cell);
    earlier_undecided = earlier_undecided || v == contact::Truth::unknown;
    if (v != contact::Truth::yes) continue;
    pipeline::Outcome r = pipeline::Outcome::collides();
    if (want_toi && !earlier_undecided) {
      if (narrow(P.volume(), cell, kToiHalvings) == Narrowing::done)
        r.toi = TimeInterval{cell.lo, cell.hi};
      else if (!cell.is_point())
        toi_cell = VolumeRootCell{cell.lo, cell.hi, cell.sign_at_lo};
    }
    return r;
  }
  return earlier_undecided ? pipeline::Outcome::undecided() : pipeline::Outcome::separate();
}

}  // namespace exactccd::filter::interval
