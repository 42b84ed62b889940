#include "questions/contact_question.hpp"

#include "exact/exact_ccd.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "filter/static_stage.hpp"
#include "filter/toi_narrowing.hpp"
#include "filter/unit_scaling.hpp"
#include "filter/volume_exclusion.hpp"
#include "pipeline/run_stages.hpp"
#include "separation/separating_plane.hpp"

namespace exactccd::questions {
namespace {

using pipeline::Work;

/// The contact question's stage order, cheapest first (docs/design.md, 5). Its TOI is asked for
/// whenever tmax < 1 (a collision counts only if it is before tmax). Findings
/// (pipeline/outcome.hpp) in this list: volume_out_of_range is written by VolumeExclusionStage
/// and read by VolumeRetryStage (retry on the scaled query only where stage 1's range limits
/// stopped it); toi_cell is written by IntervalStage (a collision proved, its root cell isolated
/// but not narrowed) and read by ToiInCellStage (narrows it); rule_toi_cell likewise (a root of
/// another polynomial of the rule: V identically zero, or factored), read by RuleRootToiStage.
/// used_gmp and use are not used here:
/// the integer stages count at their own counters, and the exact path takes the contact rule whole.
template <class Query>
std::optional<TimeInterval> through_contact_stages(const Query& q, const Question& asked, StageCounters* counters) {
  Work<Query> work{q, {asked.params, asked.want_toi || !asked.params.whole_step()}, counters};
  const std::optional<TimeInterval> toi =
      run_stages(work,
                 filter::VolumeExclusionStage{},       // 1. V(t) != 0 on [0, 1] (static error bound)
                 filter::VolumeRetryStage{},           //    1. again on the query scaled towards 1, if out of range
                 filter::StaticQueryStage{},           //    nothing moves: CGAL's exact static predicates at t = 0
                 separation::SeparatingPlaneStage{},   //    a plane separates them at t0 and at t1: apart throughout
                 filter::UnitScalingStage{},           //    the query scaled towards 1 for the stages below
                 filter::IntervalStage{},              // 2. V's roots and the in-plane rule in intervals
                 filter::ToiInCellStage{},             //    a collision's TOI in its root cell (double-double)
                 filter::RuleRootToiStage{},           //    the TOI at a root of another rule polynomial (exact signs)
                 filter::FixedIntegerStage{},          // 3a. exact, in 1024-bit integers (no allocation)
                 filter::IntegerStage{},               // 3. exact, in GMP integers
                 exact::ExactContactStage{});          // 4. CGAL's algebraic kernel: always decides
  return pipeline::cut(toi, asked.params.tmax);
}

}  // namespace

std::optional<TimeInterval> contact_question(const VertexFaceQuery& q, const Question& question, StageCounters* counters) {
  return through_contact_stages(q, question, counters);
}

std::optional<TimeInterval> contact_question(const EdgeEdgeQuery& q, const Question& question, StageCounters* counters) {
  return through_contact_stages(q, question, counters);
}

}  // namespace exactccd::questions
