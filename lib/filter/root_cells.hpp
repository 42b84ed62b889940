// The handover of the contact question's interval stage (interval_stage.hpp) to its TOI stages
// (toi_narrowing.hpp): the root cell of a collision it proved, isolated but not narrowed to
// adjacent doubles.
#pragma once

#include <optional>

namespace exactccd::filter {

/// A dyadic cell [lo, hi] of [0, 1] holding exactly one root of the contact volume V, a simple
/// one, with V's (nonzero) sign at lo (the opposite at hi).
struct VolumeRootCell {
  double lo = 0, hi = 1;
  int sign_at_lo = 0;
};

/// A polynomial of the contact rule other than V, named so that a later stage can build it
/// exactly from the query: one of the in-plane polynomials (contact::visit_in_plane_poly's
/// index in_plane >= 0), or else coordinate `coordinate` of the relative motion from row `from`
/// to row `to` of the query (contact::relative_motion: linear; a factor of V in the interval
/// stage's factored view).
struct RulePoly {
  int in_plane = -1;
  int from = 0, to = 0, coordinate = 0;
};

/// A root cell of a polynomial `poly` of the contact rule other than V: the open cell (lo, hi)
/// of doubles holds exactly one root t* of it, a simple one, with its (nonzero) sign sign_at_lo
/// at lo (the opposite at hi); the rule holds at t*; and every other candidate time where
/// contact holds or is undecided is >= later_from. So t* is the TOI when the tightest double
/// interval around it ends at or before later_from.
struct RuleRootCell {
  double lo = 0, hi = 1;
  int sign_at_lo = 0;
  RulePoly poly;
  double later_from = 0;
};

/// What the interval stage hands over to the TOI stages.
struct RootCells {
  /// The TOI is V's simple root in this cell (the interval stage proved the collision and
  /// isolated the root, but did not narrow it to adjacent doubles); read by ToiInCellStage.
  std::optional<VolumeRootCell> toi_cell;
  /// V identically zero or factored: the TOI is the root in this cell of a polynomial of the
  /// rule if it is no later than the cell's later_from (the interval stage proved the collision
  /// there and isolated the root, but did not narrow it); read by RuleRootToiStage.
  std::optional<RuleRootCell> rule_toi_cell;
};

}  // namespace exactccd::filter
