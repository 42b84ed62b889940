#include "questions/contact_question.hpp"

#include "exact/exact_ccd.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "filter/static_stage.hpp"
#include "filter/toi_narrowing.hpp"
#include "filter/unit_scaling.hpp"
#include "filter/volume_exclusion.hpp"
#include "pipeline/block.hpp"
#include "pipeline/run_stages.hpp"
#include "separation/separating_plane.hpp"

namespace exactccd::questions {
namespace {

using pipeline::Work;

/// The contact question's stage order, cheapest first (docs/design.md, 5). ContactFindings in
/// this list: volume_out_of_range is written by VolumeExclusionStage (per query or per lane of
/// its block form) and read by VolumeRetryStage (retry on the scaled query only where stage
/// 1's range limits stopped it); toi_cell is written by IntervalStage (a collision proved, its
/// root cell isolated but not narrowed) and read by ToiInCellStage (narrows it); rule_toi_cell
/// likewise (a root of another polynomial of the rule: V identically zero, or factored), read by
/// RuleRootToiStage. The integer stages count at their own counters, and the exact path takes
/// the contact rule whole.
constexpr pipeline::StageList kContactStages{
    filter::VolumeExclusionStage{},       // 1. V(t) != 0 on [0, 1] (static error bound); block form
    filter::VolumeRetryStage{},           //    1. again on the query scaled towards 1, if out of range
    filter::StaticQueryStage{},           //    nothing moves: CGAL's exact static predicates at t = 0
    separation::SeparatingPlaneStage{},   //    a plane separates them at t0 and at t1: apart throughout
    filter::UnitScalingStage{},           //    the query scaled towards 1 for the stages below
    filter::IntervalStage{},              // 2. V's roots and the in-plane rule in intervals
    filter::ToiInCellStage{},             //    a collision's TOI in its root cell (double-double)
    filter::RuleRootToiStage{},           //    the TOI at a root of another rule polynomial (exact signs)
    filter::FixedIntegerStage{},          // 3a. exact, in 1024-bit integers (no allocation)
    filter::IntegerStage{},               // 3. exact, in GMP integers
    exact::ExactContactStage{}};          // 4. CGAL's algebraic kernel: always decides

/// The question the stages are asked: the TOI too whenever tmax < 1 (a collision counts only if
/// it is before tmax: pipeline::cut).
Question as_asked(const Question& q) { return {q.params, q.want_toi || !q.params.whole_step()}; }

template <class Query>
std::optional<TimeInterval> through_contact_stages(const Query& q, const Question& asked, StageCounters* counters) {
  Work<Query, ContactFindings> work{q, as_asked(asked), counters};
  return pipeline::cut(kContactStages.run(work), asked.params.tmax);
}

template <class Query>
void batch_through_contact_stages(const Query* queries, std::size_t count, const Question& asked,
                                  StageCounters* counters, std::optional<TimeInterval>* answers) {
  pipeline::run_batch<ContactFindings>(kContactStages, queries, count, as_asked(asked), counters,
                                       [&](std::size_t i, const std::optional<TimeInterval>& toi) {
                                         answers[i] = pipeline::cut(toi, asked.params.tmax);
                                       });
}

template <class Query>
std::optional<TimeInterval> resumed(const Query& q, const Question& asked, const ContactFindings& findings) {
  return pipeline::cut(pipeline::resume(kContactStages, q, as_asked(asked), nullptr, findings, false),
                       asked.params.tmax);
}

}  // namespace

std::optional<TimeInterval> contact_question(const VertexFaceQuery& q, const Question& question, StageCounters* counters) {
  return through_contact_stages(q, question, counters);
}
std::optional<TimeInterval> contact_question(const EdgeEdgeQuery& q, const Question& question, StageCounters* counters) {
  return through_contact_stages(q, question, counters);
}

void contact_question(const VertexFaceQuery* queries, std::size_t count, const Question& question,
                      StageCounters* counters, std::optional<TimeInterval>* answers) {
  batch_through_contact_stages(queries, count, question, counters, answers);
}
void contact_question(const EdgeEdgeQuery* queries, std::size_t count, const Question& question,
                      StageCounters* counters, std::optional<TimeInterval>* answers) {
  batch_through_contact_stages(queries, count, question, counters, answers);
}

pipeline::BlockPrefix<ContactFindings> contact_block_stages(const pipeline::QueryLanes<VertexFaceQuery>& lanes) {
  return pipeline::run_block_prefix<ContactFindings>(kContactStages, lanes, Question{{}, true}, nullptr);
}
pipeline::BlockPrefix<ContactFindings> contact_block_stages(const pipeline::QueryLanes<EdgeEdgeQuery>& lanes) {
  return pipeline::run_block_prefix<ContactFindings>(kContactStages, lanes, Question{{}, true}, nullptr);
}

std::optional<TimeInterval> contact_question_resumed(const VertexFaceQuery& q, const Question& question,
                                                     const ContactFindings& findings) {
  return resumed(q, question, findings);
}
std::optional<TimeInterval> contact_question_resumed(const EdgeEdgeQuery& q, const Question& question,
                                                     const ContactFindings& findings) {
  return resumed(q, question, findings);
}

}  // namespace exactccd::questions
