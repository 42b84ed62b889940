// The interval stage when the volume V vanishes identically (coplanar for all t; docs/design.md,
// 5.2, item 4): the candidates are 0, 1 and the roots of the in-plane polynomials the rule can
// consult, each examined over its own root cell. The answer is certain when every candidate is
// decided; the TOI when the earliest contact is an exact point that no undecided cell
// precedes. When it is a root cell instead, the cell is handed over (RuleRootCell) for
// narrowing by exact signs (filter/toi_narrowing.cpp) with the earliest start of every other
// contact or undecided cell: the root is the TOI when its tightest enclosure ends there or
// before.
#pragma once

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <optional>

#include "filter/interval/in_plane_over_cell.hpp"
#include "filter/interval/isolation.hpp"
#include "filter/root_cells.hpp"
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

  /// Examines the candidate root of `defining` in `cell`; `poly` is defining's index among the
  /// in-plane polynomials (contact::visit_in_plane_poly), or -1 for an end of [0, 1].
  template <class Defining>
  void examine(const Defining& defining, bool is_rule_poly, RootCell cell, int poly) {
    const contact::Truth v = in_plane_verdict(P_, defining, is_rule_poly, cell);
    if (v == contact::Truth::no) return;
    starts_.push_back(cell.lo);  // contact or undecided: a time the TOI cannot be after
    if (v == contact::Truth::unknown) {
      uncertain_ = true;
      earliest_undecided_ = std::min(earliest_undecided_, cell.lo);
    } else {
      const TimeInterval t{cell.lo, cell.hi};
      if (!earliest_contact_ || t.lo < earliest_contact_->lo || (t.lo == earliest_contact_->lo && t.hi < earliest_contact_->hi)) {
        earliest_contact_ = t;
        earliest_cell_ = RuleRootCell{cell.lo, cell.hi, cell.sign_at_lo, RulePoly{poly}, kInf};
        earliest_start_ = starts_.size() - 1;
      }
    }
  }

  /// Examines every root of the rule's polynomial p, of index `poly` among the in-plane
  /// polynomials; returns how many there are.
  template <int D>
  std::size_t roots_of(const contact::Poly<Interval, D>& p, int poly) {
    if (failed_ || exactly_zero(p)) return 0;
    RootCells cells;
    if (isolate_roots(p, cells, false) == Isolation::failed) {
      failed_ = true;
      return 0;
    }
    for (const RootCell& c : cells) examine(p, true, c, poly);
    return cells.size();
  }

  /// The stage's outcome once every candidate is examined; with want_toi, a collision whose
  /// TOI is not certain here may hand over its root cell in `toi_cell`.
  pipeline::Outcome outcome(bool want_toi, std::optional<RuleRootCell>& toi_cell) const {
    if (failed_) return pipeline::Outcome::undecided();
    if (!earliest_contact_) return uncertain_ ? pipeline::Outcome::undecided() : pipeline::Outcome::separate();
    pipeline::Outcome r = pipeline::Outcome::collides();
    if (!want_toi) return r;
    // The TOI is certain when the earliest contact is an exact point that no undecided cell
    // precedes (a contact cell (lo, hi) is not narrowed to a tight enclosure here).
    if (earliest_contact_->lo == earliest_contact_->hi) {
      if (earliest_undecided_ > earliest_contact_->lo) r.toi = earliest_contact_;
      return r;
    }
    // A root cell (lo, hi) of an in-plane polynomial where the rule holds at the root t*.
    // Every other contact or undecided candidate is a root r (or an end of [0, 1]) in a cell
    // starting at s >= later_from, so r >= s >= later_from (r = s for a point cell, r > s for
    // an open one): when t* <= later_from, no candidate before t* can hold, and t* is the TOI
    // (the candidate argument: the earliest contact is a candidate where the rule holds).
    RuleRootCell cell = earliest_cell_;
    for (std::size_t i = 0; i < starts_.size(); ++i)
      if (i != earliest_start_) cell.later_from = std::min(cell.later_from, starts_[i]);
    if (cell.later_from > cell.lo) toi_cell = cell;  // else some other candidate may be earlier
    return r;
  }

  /// Isolation failed for some polynomial.
  bool failed() const { return failed_; }

 private:
  const Polys& P_;
  bool failed_ = false, uncertain_ = false;
  std::optional<TimeInterval> earliest_contact_;  // among decided candidates
  RuleRootCell earliest_cell_;          // its root cell (when not a point)
  double earliest_undecided_ = kInf;              // the smallest lo of an undecided cell
  // The starts of every contact or undecided cell (at most 2 ends and the roots of 3 + 4 + 16
  // polynomials), and the earliest contact's position among them.
  boost::container::small_vector<double, 8> starts_;
  std::size_t earliest_start_ = 0;
};

/// The stage when V vanishes identically: see the file comment.
template <class Polys>
pipeline::Outcome coplanar_strategy(const Polys& P, bool want_toi, std::optional<RuleRootCell>& toi_cell) {
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
  candidates.examine(constant, false, RootCell{0.0, 0.0, 0}, -1);
  candidates.examine(constant, false, RootCell{1.0, 1.0, 0}, -1);
  // Only the polynomials the rule can consult somewhere in [0, 1] (docs/design.md): a branch-
  // vector component nonzero without a root keeps the rule in its proper branch throughout; a
  // branch vector that vanishes identically, in the other.
  // Each polynomial is examined with its index in contact::for_each_in_plane_poly's order.
  bool nowhere_zero = false, identically_zero = true;
  const auto& v = contact::branch_vector(P);
  int index = 0;  // of the branch vector's components: 0, 1, 2
  for (const auto* component : {&v.x, &v.y, &v.z}) {
    const int poly = index++;
    if (exactly_zero(*component)) continue;
    identically_zero = false;
    if (candidates.roots_of(*component, poly) == 0 && !candidates.failed() &&
        certain_sign((*component)(Interval(0.0, 1.0))) != 0)
      nowhere_zero = true;  // no root and certainly nonzero on [0, 1]
  }
  const auto add_from = [&](int first) {  // each polynomial with its index, from `first` on
    return [&candidates, index = first](const auto& p) mutable { candidates.roots_of(p, index++); };
  };
  if (!identically_zero) contact::for_each_proper_poly(P, add_from(contact::kFirstProperPoly));
  if (!nowhere_zero) contact::for_each_degenerate_poly(P, add_from(contact::first_degenerate_poly(P)));
  return candidates.outcome(want_toi, toi_cell);
}

}  // namespace exactccd::filter::interval
