// The filtered method: stages from cheapest to exact, each deciding what it can certify.
//   1. volume exclusion (static error bound, doubles): V(t) != 0 on [0, 1] => no collision;
//   1b. nothing moves: CGAL's exact static predicates (orientation, collinearity) at t = 0;
//   2. interval stage (CGAL::Interval_nt): root isolation and in-plane signs;
//   3. integer stage (GMP integers, small exact kernel for degree <= 4);
//   4. CGAL path (GMP rationals, CGAL's Algebraic_kernel_d_1): always decides.
// The answer is always the exact one; only the time taken depends on the stage.
#pragma once

#include <optional>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"

namespace exactccd::filter {

/// A vertex-face query through the filter stages, counting the deciding stage in `counters`
/// (may be null): the tightest TOI when `want_toi`, otherwise, for a collision, the placeholder
/// interval [0, 0] (only its presence matters). Exact.
std::optional<TimeInterval> filtered(const VertexFaceQuery& q, bool want_toi, StageCounters* counters);

/// An edge-edge query through the filter stages; see filtered(const VertexFaceQuery&, ...).
std::optional<TimeInterval> filtered(const EdgeEdgeQuery& q, bool want_toi, StageCounters* counters);

}  // namespace exactccd::filter
