// Narrowing a contact time of impact to the tightest double interval (docs/design.md, 5.2,
// "TOI"), after the interval stage: it proved the collision and isolated the TOI as the simple
// root of V in a cell (pipeline::VolumeRootCell), a few bits short of adjacent doubles. A
// long-double Newton guess picks a double; V's signs at it and at its neighbour, certified in
// double-double arithmetic (volume_sign.hpp), exact in GMP only where those stay uncertain,
// usually settle it (numeric/root_narrowing.hpp).
#pragma once

#include <optional>

#include "exactccd/types.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// The tightest double interval around the root of V in `cell`, by exact signs of V at doubles;
/// nullopt when the exact signs at the cell's ends contradict the cell (then a later stage
/// decides the whole query).
std::optional<TimeInterval> toi_in_cell(const VertexFaceQuery& q, const pipeline::VolumeRootCell& cell);

/// See toi_in_cell(const VertexFaceQuery&, const pipeline::VolumeRootCell&).
std::optional<TimeInterval> toi_in_cell(const EdgeEdgeQuery& q, const pipeline::VolumeRootCell& cell);

/// The contact question's stage after the interval stage: the TOI of a collision it proved, in
/// the root cell it handed over (findings.toi_cell).
struct ToiInCellStage {
  /// Never counted: it runs only after the interval stage decided (and counted) the answer.
  static constexpr pipeline::Counter counter = &StageCounters::interval;
  /// The TOI in the handed-over cell, when there is one.
  template <class Query>
  pipeline::Outcome operator()(const pipeline::Work<Query>& work) const {
    if (!work.collides || !work.findings.toi_cell) return pipeline::Outcome::undecided();
    if (const auto toi = toi_in_cell(work.query(), *work.findings.toi_cell)) return pipeline::Outcome::collides(toi);
    return pipeline::Outcome::undecided();
  }
};

}  // namespace exactccd::filter
