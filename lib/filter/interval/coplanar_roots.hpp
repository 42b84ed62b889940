// The interval stage when the volume V vanishes identically (coplanar for all t; docs/design.md,
// 5.2, item 4): the candidates are 0, 1 and the roots of the in-plane polynomials the rule can
// consult, each examined over its own root cell. The answer is certain when every candidate is
// decided; the TOI only when the earliest contact is an exact point that no undecided cell
// precedes.
#pragma once

#include <algorithm>
#include <optional>

#include "filter/interval/in_plane_over_cell.hpp"
#include "filter/interval/isolation.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter::interval {

/// The in-plane rule with every sign certified over all of [0, 1]: a certain answer holds at
/// every t there (an exact [0, 0] value means the polynomial vanishes on [0, 1]).
template <class Polys>
contact::Truth rule_over_unit_interval(const Polys& P) {
  return contact::in_plane_contact(P, IntervalSignOracle{Interval(0.0, 1.0)});
}

/// The candidates of a coplanar query examined one by one, and what they showed.
template <class Polys>
class CoplanarCandidates {
 public:
  explicit CoplanarCandidates(const Polys& P) : P_(P) {}

  /// Examines the candidate root of `defining` in `cell`.
  template <class Defining>
  void examine(const Defining& defining, bool is_rule_poly, RootCell cell) {
    const contact::Truth v = in_plane_verdict(P_, defining, is_rule_poly, cell);
    if (v == contact::Truth::unknown) {
      uncertain_ = true;
      earliest_undecided_ = std::min(earliest_undecided_, cell.lo);
    } else if (v == contact::Truth::yes) {
      const TimeInterval t{cell.lo, cell.hi};
      if (!earliest_contact_ || t.lo < earliest_contact_->lo || (t.lo == earliest_contact_->lo && t.hi < earliest_contact_->hi))
        earliest_contact_ = t;
    }
  }

  /// Examines every root of the rule's polynomial p; returns how many there are.
  template <int D>
  std::size_t roots_of(const contact::Poly<Interval, D>& p) {
    if (failed_ || exactly_zero(p)) return 0;
    RootCells cells;
    if (isolate_roots(p, cells, false) == Isolation::failed) {
      failed_ = true;
      return 0;
    }
    for (const RootCell& c : cells) examine(p, true, c);
    return cells.size();
  }

  /// The stage's outcome once every candidate is examined.
  pipeline::Outcome outcome(bool want_toi) const {
    if (failed_) return pipeline::Outcome::undecided();
    if (!earliest_contact_) return uncertain_ ? pipeline::Outcome::undecided() : pipeline::Outcome::separate();
    pipeline::Outcome r = pipeline::Outcome::collides();
    // The TOI is certain when the earliest contact is an exact point that no undecided cell
    // precedes (a contact cell (lo, hi) is not narrowed to a tight enclosure here).
    if (want_toi && earliest_contact_->lo == earliest_contact_->hi && earliest_undecided_ > earliest_contact_->lo)
      r.toi = earliest_contact_;
    return r;
  }

  /// Isolation failed for some polynomial.
  bool failed() const { return failed_; }

 private:
  const Polys& P_;
  bool failed_ = false, uncertain_ = false;
  std::optional<TimeInterval> earliest_contact_;  // among decided candidates
  double earliest_undecided_ = kInf;              // the smallest lo of an undecided cell
};

/// The stage when V vanishes identically: see the file comment.
template <class Polys>
pipeline::Outcome coplanar_strategy(const Polys& P, bool want_toi) {
  // First the rule over all of [0, 1] at once: a sign certified over the whole interval holds
  // at every t in it, so a certain answer is the answer at every t (a certain contact holds at
  // t = 0: the TOI is exactly 0). This decides static and slowly moving coplanar pairs whose
  // rule hinges on one certain sign, even when another polynomial of the rule (never consulted
  // for the answer) is too close to zero for its roots to be isolated below.
  switch (rule_over_unit_interval(P)) {
    case contact::Truth::no:
      return pipeline::Outcome::separate();
    case contact::Truth::yes:
      return pipeline::Outcome::collides(want_toi ? std::optional<TimeInterval>(TimeInterval{0.0, 0.0}) : std::nullopt);
    case contact::Truth::unknown:
      break;
  }
  CoplanarCandidates<Polys> candidates(P);
  const contact::Poly<Interval, 0> constant{{Interval(1)}};  // defines no root: ends of [0, 1]
  candidates.examine(constant, false, RootCell{0.0, 0.0, 0});
  candidates.examine(constant, false, RootCell{1.0, 1.0, 0});
  // Only the polynomials the rule can consult somewhere in [0, 1] (docs/design.md): a branch-
  // vector component nonzero without a root keeps the rule in its proper branch throughout; a
  // branch vector that vanishes identically, in the other.
  bool nowhere_zero = false, identically_zero = true;
  const auto& v = contact::branch_vector(P);
  for (const auto* component : {&v.x, &v.y, &v.z}) {
    if (exactly_zero(*component)) continue;
    identically_zero = false;
    if (candidates.roots_of(*component) == 0 && !candidates.failed() &&
        certain_sign((*component)(Interval(0.0, 1.0))) != 0)
      nowhere_zero = true;  // no root and certainly nonzero on [0, 1]
  }
  const auto add = [&](const auto& p) { candidates.roots_of(p); };
  if (!identically_zero) contact::for_each_proper_poly(P, add);
  if (!nowhere_zero) contact::for_each_degenerate_poly(P, add);
  return candidates.outcome(want_toi);
}

}  // namespace exactccd::filter::interval
