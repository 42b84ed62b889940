// The in-plane contact rule over a root cell of the interval stage (docs/design.md, 5.2,
// "Signs at a root"): at a root t* of a polynomial that defines the cell (V, or a factor of it,
// or one of the rule's own polynomials), the rule's answer from signs certified over the cell,
// which holds t*. Where a sign is uncertain the cell is narrowed by certified halving of the
// defining polynomial and the rule retried, while that makes progress.
#pragma once

#include "contact/contact_rule.hpp"
#include "filter/interval/isolation.hpp"
#include "filter/interval/narrowing.hpp"
#include "filter/interval/values.hpp"

namespace exactccd::filter::interval {

// Halvings spent narrowing a TOI cell in intervals before handing it to the double-double /
// exact narrowing (toi_in_cell): interval signs of V fail a few bits short of adjacent doubles
// for most roots (design.md, 5.2), so a long interval bisection mostly wastes time; 16 still
// finds exact dyadic roots of small-integer input (t = 1/2, 3/8, ...) here.
inline constexpr int kToiHalvings = 16;
// Halvings that reach adjacent doubles from any cell of [0, 1] (every double of [0, 1] is at
// most 1075 halvings deep).
inline constexpr int kAllHalvings = 1100;

/// The rule over the cell from the terms' values over it (values.hpp: no polynomial built), and
/// when those are uncertain, over the cell narrowed by 16 halvings of `defining`, then to
/// consecutive doubles (the values' enclosure tightens with the cell).
template <class Polys, int D>
contact::Truth rule_from_values(const Polys& P, const contact::Poly<Interval, D>& defining, RootCell& cell) {
  contact::Truth t = in_plane_rule_over(P, cell);
  for (const int halvings : {kToiHalvings, kAllHalvings}) {
    if (t != contact::Truth::unknown || cell.is_point() || !narrowed(defining, cell, halvings)) break;
    t = in_plane_rule_over(P, cell);
  }
  return t;
}

/// The rule over the cell from the rule's polynomials evaluated over it, narrowing the cell (16
/// halvings, then to consecutive doubles) and retrying while that makes progress. When
/// `defining` is one of the rule's own polynomials its sign is 0 (the cell holds its root).
template <class Polys, int D>
contact::Truth rule_from_polynomials(const Polys& P, const contact::Poly<Interval, D>& defining,
                                     bool defining_is_rule_poly, RootCell& cell) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const IntervalSignOracle oracle{Interval(cell.lo, cell.hi), defining_is_rule_poly ? &defining : nullptr};
    const contact::Truth t = contact::in_plane_contact(P, oracle);
    if (t != contact::Truth::unknown || cell.is_point()) return t;
    if (!narrowed(defining, cell, attempt == 0 ? kToiHalvings : kAllHalvings)) return contact::Truth::unknown;
  }
  return contact::Truth::unknown;
}

/// The in-plane rule at the root of `defining` in `cell` (narrowed on the way). Unless
/// `defining` is one of the rule's own polynomials (whose zero the oracle must know), first
/// from the terms' values, then from the polynomials.
template <class Polys, int D>
contact::Truth in_plane_verdict(const Polys& P, const contact::Poly<Interval, D>& defining, bool defining_is_rule_poly,
                                RootCell& cell) {
  if (!defining_is_rule_poly)
    if (const contact::Truth t = rule_from_values(P, defining, cell); t != contact::Truth::unknown) return t;
  return rule_from_polynomials(P, defining, defining_is_rule_poly, cell);
}

}  // namespace exactccd::filter::interval
