// The contact question (d = 0) of vertex-face and edge-edge queries by the filtered method: its
// stage list (contact_question.cpp; docs/design.md, 5).
#pragma once

#include <optional>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::questions {

using pipeline::Question;

/// The contact question (question.params.min_distance == 0, tmax in (0, 1]) of a vertex-face
/// query through the contact stages, counted in `counters` (may be null): the tightest TOI in
/// [0, tmax] when question.want_toi, otherwise, for a collision, kCollisionWithoutToi; nullopt
/// when the primitives do not touch in [0, tmax]. Exact.
std::optional<TimeInterval> contact_question(const VertexFaceQuery& q, const Question& question, StageCounters* counters);

/// See contact_question(const VertexFaceQuery&, const Question&, StageCounters*).
std::optional<TimeInterval> contact_question(const EdgeEdgeQuery& q, const Question& question, StageCounters* counters);

}  // namespace exactccd::questions
