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

/// One query through the stages. Kind bundles the per-primitive functions. Without want_toi a
/// collision is returned as the placeholder interval [0, 0] (only its presence matters).
template <class Kind, class Query>
std::optional<TimeInterval> filtered_toi(const Query& input, bool want_toi, StageCounters* counters) {
  if (Kind::volume_excluded(input)) {
    count(counters, &StageCounters::volume_exclusion);
    return std::nullopt;
  }
  // Past the hot path: bring the scene's magnitude near 1 (exactly) so that huge or tiny
  // coordinates do not overflow or underflow the filters; answers are unchanged.
  bool scaled = false;
  const Query q = scaled_to_unit(input, scaled);
  if (scaled && Kind::volume_excluded(q)) {
    count(counters, &StageCounters::volume_exclusion);
    return std::nullopt;
  }
  if (is_static(q)) {  // contact does not depend on t: decided at t = 0, the TOI if it holds
    count(counters, &StageCounters::static_predicates);
    if (!contact_at_end(q, 0)) return std::nullopt;
    return want_toi ? std::optional<TimeInterval>(TimeInterval{0.0, 0.0}) : kCollides;
  }
  const StageResult interval = Kind::interval_stage(q, want_toi);
  if (interval.verdict != Verdict::uncertain) {
    count(counters, &StageCounters::interval);
    if (interval.verdict == Verdict::no_collision || !want_toi || interval.toi)
      return answer(interval);
    count(counters, &StageCounters::toi_refined);  // collision certain, TOI not yet
    if (interval.toi_cell)  // the TOI is V's simple root in this cell: narrow it exactly
      if (auto toi = toi_in_cell(q, *interval.toi_cell)) return toi;
  }
  const StageResult integer = Kind::integer_stage(q, want_toi);
  if (integer.verdict != Verdict::uncertain) {
    if (interval.verdict == Verdict::uncertain) count(counters, &StageCounters::integer);
    return answer(integer);
  }
  if (interval.verdict == Verdict::uncertain) count(counters, &StageCounters::exact);
  const auto rational = exact::to_rational(q);
  if (!want_toi) return Kind::exact_ccd(rational) ? kCollides : std::nullopt;
  return Kind::exact_toi(rational);
}

struct VertexFace {
  static bool volume_excluded(const VertexFaceQuery& q) { return vertex_face_volume_excluded(q); }
  static StageResult interval_stage(const VertexFaceQuery& q, bool want_toi) {
    return vertex_face_interval_stage(q, want_toi);
  }
  static StageResult integer_stage(const VertexFaceQuery& q, bool want_toi) {
    return vertex_face_integer_stage(q, want_toi);
  }
  static bool exact_ccd(const RationalVertexFaceQuery& q) { return exact::vertex_face_ccd(q); }
  static std::optional<TimeInterval> exact_toi(const RationalVertexFaceQuery& q) {
    return exact::vertex_face_toi(q);
  }
};

struct EdgeEdge {
  static bool volume_excluded(const EdgeEdgeQuery& q) { return edge_edge_volume_excluded(q); }
  static StageResult interval_stage(const EdgeEdgeQuery& q, bool want_toi) {
    return edge_edge_interval_stage(q, want_toi);
  }
  static StageResult integer_stage(const EdgeEdgeQuery& q, bool want_toi) {
    return edge_edge_integer_stage(q, want_toi);
  }
  static bool exact_ccd(const RationalEdgeEdgeQuery& q) { return exact::edge_edge_ccd(q); }
  static std::optional<TimeInterval> exact_toi(const RationalEdgeEdgeQuery& q) {
    return exact::edge_edge_toi(q);
  }
};

}  // namespace

bool vertex_face_ccd(const VertexFaceQuery& q, StageCounters* counters) {
  return filtered_toi<VertexFace>(q, false, counters).has_value();
}

bool edge_edge_ccd(const EdgeEdgeQuery& q, StageCounters* counters) {
  return filtered_toi<EdgeEdge>(q, false, counters).has_value();
}

std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, StageCounters* counters) {
  return filtered_toi<VertexFace>(q, true, counters);
}

std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, StageCounters* counters) {
  return filtered_toi<EdgeEdge>(q, true, counters);
}

}  // namespace exactccd::filter
