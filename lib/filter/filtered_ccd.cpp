#include "filter/filtered_ccd.hpp"

#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "filter/integer_stage.hpp"
#include "filter/interval_stage.hpp"
#include "filter/normalize.hpp"
#include "filter/toi_narrowing.hpp"
#include "filter/static_stage.hpp"
#include "filter/volume_exclusion.hpp"

namespace exactccd::filter {
namespace {

void count(StageCounters* counters, std::uint64_t StageCounters::*stage) {
  if (counters) ++(counters->*stage);
}

/// A collision without a TOI, for callers that only ask whether the primitives collide.
const std::optional<TimeInterval> kCollides = TimeInterval{};

std::optional<TimeInterval> answer(const StageResult& r) {
  return r.verdict == Verdict::collision ? (r.toi ? r.toi : kCollides) : std::nullopt;
}

/// One query through the stages (each stage an overload on the query's kind). Without want_toi
/// a collision is returned as the placeholder interval [0, 0] (only its presence matters).
template <class Query>
std::optional<TimeInterval> through_stages(const Query& input, bool want_toi, StageCounters* counters) {
  const Exclusion exclusion = volume_exclusion(input);
  if (exclusion == Exclusion::excluded) {
    count(counters, &StageCounters::volume_exclusion);
    return std::nullopt;
  }
  // Past the hot path: bring the scene's magnitude near 1 (exactly) so that huge or tiny
  // coordinates do not overflow or underflow the filters; answers are unchanged. Stage 1 is
  // retried only where its range limits stopped it (volume_exclusion: else the scaled query's
  // rounded values are the same up to a power of two).
  bool scaled = false;
  const Query q = scaled_to_unit(input, scaled);
  if (scaled && exclusion == Exclusion::out_of_range && volume_excluded(q)) {
    count(counters, &StageCounters::volume_exclusion);
    return std::nullopt;
  }
  if (is_static(q)) {  // contact does not depend on t: decided at t = 0, the TOI if it holds
    count(counters, &StageCounters::static_predicates);
    if (!contact_at_end(q, 0)) return std::nullopt;
    return want_toi ? std::optional<TimeInterval>(TimeInterval{0.0, 0.0}) : kCollides;
  }
  const StageResult interval = interval_stage(q, want_toi);
  if (interval.verdict != Verdict::uncertain) {
    count(counters, &StageCounters::interval);
    if (interval.verdict == Verdict::no_collision || !want_toi || interval.toi)
      return answer(interval);
    count(counters, &StageCounters::toi_refined);  // collision certain, TOI not yet
    if (interval.toi_cell)  // the TOI is V's simple root in this cell: narrow it exactly
      if (auto toi = toi_in_cell(q, *interval.toi_cell)) return toi;
  }
  // The integer stage, first in fixed-width integers (no allocation), then in GMP when the
  // fixed one overflows or is not tried (integer_stage.hpp, fixed_integer_stage).
  const StageResult fixed = fixed_integer_stage(q, want_toi);
  if (fixed.verdict != Verdict::uncertain) {
    if (interval.verdict == Verdict::uncertain) count(counters, &StageCounters::fixed_integer);
    return answer(fixed);
  }
  const StageResult integer = integer_stage(q, want_toi);
  if (integer.verdict != Verdict::uncertain) {
    if (interval.verdict == Verdict::uncertain) count(counters, &StageCounters::integer);
    return answer(integer);
  }
  if (interval.verdict == Verdict::uncertain) count(counters, &StageCounters::exact);
  const auto rational = exact::to_rational(q);
  if (!want_toi) return exact::ccd(rational) ? kCollides : std::nullopt;
  return exact::toi(rational);
}

}  // namespace

std::optional<TimeInterval> filtered(const VertexFaceQuery& q, bool want_toi, StageCounters* counters) {
  return through_stages(q, want_toi, counters);
}

std::optional<TimeInterval> filtered(const EdgeEdgeQuery& q, bool want_toi, StageCounters* counters) {
  return through_stages(q, want_toi, counters);
}

}  // namespace exactccd::filter
