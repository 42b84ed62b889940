// Stage 2 of the contact question: interval arithmetic (CGAL::Interval_nt) on the polynomials
// of the contact rule. Isolates the roots of the volume V in [0, 1] by Bernstein subdivision
// and evaluates the in-plane rule over each isolating interval; decides whenever every sign
// it needs is certain, and otherwise leaves the query to a later stage.
#pragma once

#include "exactccd/types.hpp"
#include "filter/root_cells.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::filter {

/// Stage 2 for vertex-face. With want_toi, a collision's TOI is certified, or its root cell is
/// handed over in cells.toi_cell (when it is V's simple root) or cells.rule_toi_cell
/// (a simple root of another polynomial of the rule: V identically zero, or factored), or
/// neither.
pipeline::Outcome interval_stage(const VertexFaceQuery& q, bool want_toi, RootCells& cells);

/// Stage 2 for edge-edge; see interval_stage(const VertexFaceQuery&, bool, RootCells&).
pipeline::Outcome interval_stage(const EdgeEdgeQuery& q, bool want_toi, RootCells& cells);

/// Stage 2 in the contact question's stage list (its findings hold RootCells).
struct IntervalStage {
  static constexpr pipeline::Counter counter = &StageCounters::interval;  ///< counted as
  /// The stage on work.query().
  template <class Query, class Findings>
  pipeline::Outcome operator()(pipeline::Work<Query, Findings>& work) const {
    return interval_stage(work.query(), work.question.want_toi, work.findings);
  }
};

}  // namespace exactccd::filter
