// The two methods for rigid queries (exactccd/rigid.hpp; docs/design.md, 9.3-9.4) as stage lists
// of the one protocol (pipeline/outcome.hpp), the rigid motion model's counterparts of
// methods.hpp's: the same questions (contact at d = 0, minimum separation at d > 0), the same
// shape of lists (rigid_methods.cpp).
#pragma once

#include <optional>

#include "exactccd/rigid.hpp"
#include "exactccd/stats.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::questions {

/// The answer of a valid rigid query (validated by the entry point) by the filtered method: the
/// TOI when question.want_toi, else any enclosure of it on collision; nullopt for none. Counts
/// the deciding stage in `counters` (may be null). Needs the default floating-point
/// environment (the entry points install it).
std::optional<TimeInterval> filtered_method(const RigidVertexFaceQuery& q, const pipeline::Question& question,
                                            StageCounters* counters);
/// See filtered_method(const RigidVertexFaceQuery&, const pipeline::Question&, StageCounters*).
std::optional<TimeInterval> filtered_method(const RigidEdgeEdgeQuery& q, const pipeline::Question& question,
                                            StageCounters* counters);

/// The answer of a valid rigid query by the exact method (GMP and CGAL throughout; not
/// counted): the contact rule at d = 0, the feature-pair terms at d > 0 (rigid/exact_rigid.hpp).
std::optional<TimeInterval> exact_method(const RigidVertexFaceQuery& q, const pipeline::Question& question);
/// See exact_method(const RigidVertexFaceQuery&, const pipeline::Question&).
std::optional<TimeInterval> exact_method(const RigidEdgeEdgeQuery& q, const pipeline::Question& question);

}  // namespace exactccd::questions
