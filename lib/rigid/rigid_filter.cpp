// The filtered method for rigid queries. NOT YET FILTERED: every query takes the exact path
// (counted as `exact`); the certified stages are the next step (docs/design.md, 9.4).
#include "rigid/rigid_filter.hpp"

#include "rigid/exact_rigid.hpp"

namespace exactccd::rigid {
namespace {

template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, StageCounters* counters) {
  if (counters) ++counters->exact;
  return exact_toi(to_rational(q), RationalCcdParams{params.min_distance, params.tmax});
}

}  // namespace

std::optional<TimeInterval> filtered(const RigidVertexFaceQuery& q, const CcdParams& params, bool,
                                     StageCounters* counters) {
  return answer(q, params, counters);
}
std::optional<TimeInterval> filtered(const RigidEdgeEdgeQuery& q, const CcdParams& params, bool,
                                     StageCounters* counters) {
  return answer(q, params, counters);
}

}  // namespace exactccd::rigid
