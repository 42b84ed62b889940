// Narrowing a contact time of impact to the tightest double interval (docs/design.md, 5.2,
// "TOI"), after the interval stage: it proved the collision and isolated the TOI as the simple
// root of V in a cell (VolumeRootCell), a few bits short of adjacent doubles. A
// long-double Newton guess picks a double; V's signs at it and at its neighbour, certified in
// double-double arithmetic (volume_sign.hpp), exact in GMP only where those stay uncertain,
// usually settle it; otherwise secant steps on the double-double values of V at the last two
// doubles examined (numeric/root_narrowing.hpp) land next to the root within a step or two
// (bisection before, with a guess far off, about 40 signs).
// When V vanishes identically (coplanar for all t), or factors visibly (interval/factored_roots.hpp),
// the interval stage may hand over instead the root cell of another polynomial of the rule
// (RuleRootCell: an in-plane polynomial, or a linear factor of V): narrowed the same
// way with exact signs of that polynomial in GMP (one polynomial of degree <= 4, built alone),
// it is the TOI when it ends no later than every other candidate that may hold. Before this
// stage such a TOI took the whole integer stages (10-50 us per query on data/sim's folds).
#pragma once

#include <optional>

#include "exactccd/types.hpp"
#include "filter/root_cells.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// The tightest double interval around the root of V in `cell`, by exact signs of V at doubles;
/// nullopt when the exact signs at the cell's ends contradict the cell (then a later stage
/// decides the whole query).
std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const VolumeRootCell& cell);

/// See toi_in_cell(const VertexFaceQuery&, const VolumeRootCell&).
std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const VolumeRootCell& cell);

/// The tightest double interval around the root t* of the rule's polynomial cell.poly
/// (RulePoly) in `cell`, by exact signs at doubles, when it ends at or before
/// cell.later_from (then it is the TOI: RuleRootCell); nullopt when it does not, or
/// when the exact signs at the cell's ends contradict the cell (then a later stage finds the TOI).
std::optional<TimeInterval> toi_in_rule_cell(const VertexFaceQuery& q, const RuleRootCell& cell);

/// See toi_in_rule_cell(const VertexFaceQuery&, const RuleRootCell&).
std::optional<TimeInterval> toi_in_rule_cell(const EdgeEdgeQuery& q, const RuleRootCell& cell);

/// The contact question's stage after the interval stage: the TOI of a collision it proved, in
/// the root cell it handed over (findings.toi_cell).
struct ToiInCellStage {
  /// Never counted: it runs only after the interval stage decided (and counted) the answer.
  static constexpr pipeline::Counter counter = &StageCounters::interval;
  /// The TOI in the handed-over cell, when there is one.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    if (!work.collides || !work.findings.toi_cell) return pipeline::Outcome::undecided();
    if (const auto toi = toi_in_cell(work.query(), *work.findings.toi_cell)) return pipeline::Outcome::collides(toi);
    return pipeline::Outcome::undecided();
  }
};

/// The contact question's stage after ToiInCellStage: the TOI of a collision the interval stage
/// proved at a root of another polynomial of the rule than V (V identically zero, or factored),
/// in the root cell it handed over (findings.rule_toi_cell).
struct RuleRootToiStage {
  /// Never counted: it runs only after the interval stage decided (and counted) the answer.
  static constexpr pipeline::Counter counter = &StageCounters::interval;
  /// The TOI in the handed-over cell, when it is certain there.
  template <class Query, class Findings>
  pipeline::Outcome operator()(const pipeline::Work<Query, Findings>& work) const {
    if (!work.collides || !work.findings.rule_toi_cell) return pipeline::Outcome::undecided();
    if (const auto toi = toi_in_rule_cell(work.query(), *work.findings.rule_toi_cell))
      return pipeline::Outcome::collides(toi);
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::filter
