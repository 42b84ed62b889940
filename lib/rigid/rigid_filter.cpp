// The filtered method for rigid queries: the stage order of each question (docs/design.md, 9.4),
// in one function. Each stage returns a StageResult (stage_result.hpp: the shape of issue 22's
// pipeline protocol); the first decided one answers, counted at its StageCounters entry (a stage
// that used GMP counts as `integer`); the exact path answers what none decides.
//   every d: the query normalized by powers of two (normalized.hpp; an inexact scaling skips to
//            the exact path), then a certified separating direction over the whole step
//            (direction_stage.hpp, `separating_direction`);
//   d = 0:   the interval stage on the volume's roots (contact_walk.hpp, `interval`);
//   d > 0:   for the answer alone, the contact stage first (touching in [0, tmax] is being within
//            d); then the interval walk over the feature-pair terms (separation_walk.hpp,
//            `interval`);
//   last:    the exact path (exact_rigid.hpp, `exact`).
#include "rigid/rigid_filter.hpp"

#include "rigid/contact_walk.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid/normalized.hpp"
#include "rigid/separation_walk.hpp"

namespace exactccd::rigid {
namespace {

void count(StageCounters* counters, std::uint64_t StageCounters::*counter) {
  if (counters) ++(counters->*counter);
}

/// The answer of a decided stage, counted.
std::optional<TimeInterval> take(const StageResult& r, StageCounters* counters) {
  count(counters, r.used_gmp ? &StageCounters::integer : &StageCounters::interval);
  if (r.answer == StageResult::Answer::collides) return r.toi;
  return std::nullopt;
}

template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, bool want_toi, StageCounters* counters) {
  if (const auto scaled = normalized(q, params.min_distance)) {
    const Query& nq = scaled->first;
    const double d = scaled->second;
    const DirectionFrame<Query> directions(nq);
    if (directions.separated_beyond(d)) {
      count(counters, &StageCounters::separating_direction);
      return std::nullopt;
    }
    StageResult r;
    {
      const CGAL::Protect_FPU_rounding<true> upward;  // the interval stages (they switch back where they need)
      const IntervalFrame<Query> frame(nq);
      if (params.min_distance == 0) {
        r = contact_walk(nq, frame, params.tmax, want_toi);
      } else {
        bool probe_used_gmp = false;
        if (!want_toi) {  // touching in [0, tmax] is being within d; its time bounds the earliest
          const StageResult touch = contact_walk(nq, frame, params.tmax, false);
          if (touch.answer == StageResult::Answer::collides)
            r = StageResult::collides({0.0, touch.toi->hi}, touch.used_gmp);
          probe_used_gmp = touch.used_gmp;
        }
        if (!r.decided()) r = separation_walk(nq, directions, frame, d, params.tmax, want_toi);
        r.used_gmp = r.used_gmp || probe_used_gmp;
      }
    }
    if (r.decided()) return take(r, counters);
  }
  count(counters, &StageCounters::exact);
  return exact_toi(to_rational(q), RationalCcdParams{params.min_distance, params.tmax});
}

}  // namespace

std::optional<TimeInterval> filtered(const RigidVertexFaceQuery& q, const CcdParams& params, bool want_toi,
                                     StageCounters* counters) {
  return answer(q, params, want_toi, counters);
}
std::optional<TimeInterval> filtered(const RigidEdgeEdgeQuery& q, const CcdParams& params, bool want_toi,
                                     StageCounters* counters) {
  return answer(q, params, want_toi, counters);
}

}  // namespace exactccd::rigid
