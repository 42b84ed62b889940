// The contact question (d = 0) of vertex-face and edge-edge queries by the filtered method: its
// stage list (contact_question.cpp; docs/design.md, 5), for one query and for a block of them
// (pipeline/block.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"
#include "filter/root_cells.hpp"
#include "filter/volume_exclusion.hpp"
#include "pipeline/block.hpp"
#include "pipeline/outcome.hpp"

namespace exactccd::questions {

using pipeline::Question;

/// What the contact question's stages hand over (contact_question.cpp says which stage writes
/// and reads each): stage 1's range flag and the interval stage's root cells.
struct ContactFindings : filter::VolumeRange, filter::RootCells {};

/// The contact question (question.params.contact_only(), tmax in (0, 1]) of a vertex-face
/// query through the contact stages, counted in `counters` (may be null): the tightest TOI in
/// [0, tmax] when question.want_toi, otherwise, for a collision, kCollisionWithoutToi; nullopt
/// when the primitives do not touch in [0, tmax]. Exact.
std::optional<TimeInterval> contact_question(const VertexFaceQuery& q, const Question& question, StageCounters* counters);

/// See contact_question(const VertexFaceQuery&, const Question&, StageCounters*).
std::optional<TimeInterval> contact_question(const EdgeEdgeQuery& q, const Question& question, StageCounters* counters);

/// contact_question for queries[0, count) into answers[0, count): the same stage list run on
/// blocks of queries (pipeline::run_batch), each query counted as one.
void contact_question(const VertexFaceQuery* queries, std::size_t count, const Question& question,
                      StageCounters* counters, std::optional<TimeInterval>* answers);
/// See the vertex-face batch form.
void contact_question(const EdgeEdgeQuery* queries, std::size_t count, const Question& question,
                      StageCounters* counters, std::optional<TimeInterval>* answers);

/// The contact question's block stages on a block (pipeline::run_block_prefix), for callers
/// that ask each open lane later (the scene's narrow phase: possibly twice, whether and when,
/// through contact_question_resumed). Its answers and findings do not depend on
/// question.want_toi (the block stages only prove lanes apart), nor on tmax: it is asked over
/// the whole step.
pipeline::BlockPrefix<ContactFindings> contact_block_stages(const pipeline::QueryLanes<VertexFaceQuery>& lanes);
/// See the vertex-face form.
pipeline::BlockPrefix<ContactFindings> contact_block_stages(const pipeline::QueryLanes<EdgeEdgeQuery>& lanes);

/// contact_question(q, question, nullptr) for q, the query of an open lane of
/// contact_block_stages with the findings it handed over: the per-query stages from the first
/// without a block form (never again the block stages; not counted).
std::optional<TimeInterval> contact_question_resumed(const VertexFaceQuery& q, const Question& question,
                                                     const ContactFindings& findings);
/// See the vertex-face form.
std::optional<TimeInterval> contact_question_resumed(const EdgeEdgeQuery& q, const Question& question,
                                                     const ContactFindings& findings);

}  // namespace exactccd::questions
