// The filtered method for rigid queries (docs/design.md, 9.4): certified floating-point stages,
// the exact path (exact_rigid.hpp) where they cannot decide.
#pragma once

#include <optional>

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"

namespace exactccd::rigid {

/// The answer of a valid rigid query (validate() passed) with CcdParams: its TOI when want_toi,
/// else any enclosure of it on collision. Counts the deciding stage in `counters` when given.
/// Needs the default floating-point environment (the entry points install it).
std::optional<TimeInterval> filtered(const RigidVertexFaceQuery& q, const CcdParams& params, bool want_toi,
                                     StageCounters* counters);
/// See filtered(const RigidVertexFaceQuery&, const CcdParams&, bool, StageCounters*).
std::optional<TimeInterval> filtered(const RigidEdgeEdgeQuery& q, const CcdParams& params, bool want_toi,
                                     StageCounters* counters);

}  // namespace exactccd::rigid
