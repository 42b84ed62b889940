// The filtered method for rigid queries as a stage list of the one pipeline protocol
// (pipeline/outcome.hpp, run_stages.hpp; docs/design.md 9.4). Each stage is a type with its
// counter and `Outcome operator()(Work<Query>&)`; the order, for every question, is:
//   NormalizedStage      the query and d scaled exactly by powers of two (rigid_unit_scaling.hpp) into
//                        the Work's replacement; where a scaling is inexact, the exact path
//                        answers at once (counted `exact`);
//   DirectionStage       a certified separating direction over the step (direction_stage.hpp,
//                        `separating_direction`);
//   IntervalStage        d = 0: the volume's roots (contact_walk.hpp), for edge-edge motion in a
//                        plane the plane's candidates (coplanar_walk.hpp); d > 0: for the answer
//                        alone the contact walk first (touching in [0, tmax] is being within d),
//                        then the walk over the feature-pair terms (separation_walk.hpp); one
//                        interval frame for both (`interval`, or `integer` when GMP was used);
//   ExactStage           the exact path (exact_rigid.hpp, `exact`): always decides.
#include "rigid/rigid_filter.hpp"

#include <type_traits>

#include "pipeline/outcome.hpp"
#include "pipeline/run_stages.hpp"
#include "rigid/contact_walk.hpp"
#include "rigid/coplanar_walk.hpp"
#include "rigid/direction_stage.hpp"
#include "rigid/exact_rigid.hpp"
#include "rigid/rigid_unit_scaling.hpp"
#include "rigid/rigid_separation_walk.hpp"

namespace exactccd::rigid {
namespace {

using pipeline::Counter;
using pipeline::Outcome;
using pipeline::Work;

/// The contact question on [0, tmax]: the volume's roots (contact_walk.hpp), then for edge-edge
/// queries moving in planes orthogonal to an axis (the volume vanishes identically) the plane's
/// candidates (coplanar_walk.hpp).
template <class Query>
StageResult contact_stage(const Query& q, const IntervalFrame<Query>& frame, double tmax, bool want_toi) {
  StageResult r = contact_walk(q, frame, tmax, want_toi);
  if constexpr (std::is_same_v<Query, RigidEdgeEdgeQuery>) {
    if (!r.decided()) {
      StageResult plane = coplanar_walk(q, tmax, want_toi);
      plane.used_gmp = plane.used_gmp || r.used_gmp;
      r = plane;
    }
  }
  return r;
}

/// The exact path's answer to the Work's question as an Outcome.
template <class Query>
Outcome exact_outcome(const Query& q, const pipeline::Question& question) {
  const auto t = exact_toi(to_rational(q), RationalCcdParams{question.params.min_distance, question.params.tmax});
  return t ? Outcome::collides(t) : Outcome::separate();
}

/// The query normalized into the Work's replacement (the same question: rigid_unit_scaling.hpp).
struct NormalizedStage {
  static constexpr Counter counter = &StageCounters::exact;  ///< only when it answers exactly
  template <class Query>
  Outcome operator()(Work<Query>& work) const {
    const auto scaled = unit_scaled(work.query(), work.question.params.min_distance);
    if (!scaled) return exact_outcome(work.query(), work.question);  // an inexact scaling
    work.replacement() = scaled->first;
    work.use_replacement();
    work.question.params.min_distance = scaled->second;
    return Outcome::undecided();
  }
};

/// A certified separating direction over the whole step.
struct DirectionStage {
  static constexpr Counter counter = &StageCounters::separating_direction;  ///< where it decides
  template <class Query>
  Outcome operator()(Work<Query>& work) const {
    return DirectionFrame<Query>(work.query()).separated_beyond(work.question.params.min_distance)
               ? Outcome::separate()
               : Outcome::undecided();
  }
};

/// The interval stages of both questions, on one interval frame.
struct IntervalStage {
  static constexpr Counter counter = &StageCounters::interval;  ///< where it decides (integer with GMP)
  template <class Query>
  Outcome operator()(Work<Query>& work) const {
    const Query& q = work.query();
    const double d = work.question.params.min_distance, tmax = work.question.params.tmax;
    const bool want_toi = work.question.want_toi;
    const DirectionFrame<Query> directions(q);  // (d > 0: the pairs kept apart are left out)
    StageResult r;
    {
      const CGAL::Protect_FPU_rounding<true> upward;  // the walks switch back where they need
      const IntervalFrame<Query> frame(q);
      if (d == 0) {
        r = contact_stage(q, frame, tmax, want_toi);
      } else {
        bool probe_used_gmp = false;
        if (!want_toi) {  // touching in [0, tmax] is being within d; its time bounds the earliest
          const StageResult touch = contact_stage(q, frame, tmax, false);
          if (touch.answer == StageResult::Answer::collides)
            r = StageResult::collides({0.0, touch.toi->hi}, touch.used_gmp);
          probe_used_gmp = touch.used_gmp;
        }
        if (!r.decided()) r = separation_walk(q, directions, frame, d, tmax, want_toi);
        r.used_gmp = r.used_gmp || probe_used_gmp;
      }
    }
    if (!r.decided()) return Outcome::undecided();
    Outcome o = r.answer == StageResult::Answer::collides ? Outcome::collides(r.toi) : Outcome::separate();
    if (r.used_gmp) o.counted_as = &StageCounters::integer;
    return o;
  }
};

/// The exact path: always decides.
struct ExactStage {
  static constexpr Counter counter = &StageCounters::exact;  ///< where it decides
  template <class Query>
  Outcome operator()(Work<Query>& work) const {
    return exact_outcome(work.query(), work.question);
  }
};

template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, bool want_toi, StageCounters* counters) {
  Work<Query> work{q, pipeline::Question{params, want_toi}, counters};
  return run_stages(work, NormalizedStage{}, DirectionStage{}, IntervalStage{}, ExactStage{});
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
