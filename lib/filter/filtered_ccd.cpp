#include "filter/filtered_ccd.hpp"

#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "filter/interval_stage.hpp"
#include "filter/volume_exclusion.hpp"

namespace exactccd::filter {
namespace {

void count(StageCounters* counters, std::uint64_t StageCounters::*stage) {
  if (counters) ++(counters->*stage);
}

/// One query through the stages. Kind bundles the per-primitive functions. Without want_toi a
/// collision is returned as an empty interval [0, 0] (only its presence matters).
template <class Kind, class Query>
std::optional<TimeInterval> filtered_toi(const Query& q, bool want_toi, StageCounters* counters) {
  if (Kind::volume_excluded(q)) {
    count(counters, &StageCounters::volume_exclusion);
    return std::nullopt;
  }
  const StageResult r = Kind::interval_stage(q, want_toi);
  if (r.verdict == Verdict::no_collision) {
    count(counters, &StageCounters::interval);
    return std::nullopt;
  }
  if (r.verdict == Verdict::collision) {
    count(counters, &StageCounters::interval);
    if (!want_toi) return TimeInterval{};  // the caller only asks whether they collide
    if (r.toi) return r.toi;
    count(counters, &StageCounters::exact_toi);
    return Kind::exact_toi(exact::to_rational(q));
  }
  count(counters, &StageCounters::exact);
  if (!want_toi) return Kind::exact_ccd(exact::to_rational(q)) ? std::optional(TimeInterval{}) : std::nullopt;
  return Kind::exact_toi(exact::to_rational(q));
}

struct VertexFace {
  static bool volume_excluded(const VertexFaceQuery& q) { return vertex_face_volume_excluded(q); }
  static StageResult interval_stage(const VertexFaceQuery& q, bool want_toi) {
    return vertex_face_interval_stage(q, want_toi);
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
