// The public entry points with CcdParams (minimum separation, time limit) for every kind:
// validation and dispatch.
//   d = 0, filtered: the contact filter of filtered_ccd.hpp (a point is a zero-length edge, a
//     2D query has z = 0: the edge-edge filter answers point-edge, point-point and 2D kinds),
//     its TOI cut at tmax;
//   d > 0, filtered: a certified separating direction (separating_direction.hpp); for the
//     answer alone (no TOI), then the contact filter (touching in [0, tmax] is within d); then
//     the interval stage (interval_separation.hpp), else the exact path;
//   exact: exact::toi for vertex-face and edge-edge at d = 0 (the reference of the contact
//     question), separation::exact_toi otherwise (an independent derivation at d = 0).
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "api/number_text.hpp"
#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rational.hpp"
#include "filter/filtered_ccd.hpp"
#include "filter/fp_environment.hpp"
#include "kinds/primitive_kinds.hpp"
#include "separation/exact_separation.hpp"
#include "separation/interval_separation.hpp"
#include "separation/separating_direction.hpp"

namespace exactccd {
namespace {

template <class Query>
std::string function_name(bool want_toi) {
  return "exactccd::" + std::string(kinds::kind_of<Query>::function) + (want_toi ? "_toi" : "_ccd");
}

template <class V>
bool finite_point(const V& v) {
  if constexpr (std::is_same_v<V, Vec2>)
    return std::isfinite(v.x) && std::isfinite(v.y);
  else
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Throws std::invalid_argument naming the function on a non-finite coordinate, a d that is
/// negative or not finite, a tmax outside (0, 1] or an unknown method value.
template <class Query>
void validate(const Query& q, const CcdParams& p, Method method, bool want_toi) {
  for (const auto& v : rows(q))
    if (!finite_point(v))
      throw std::invalid_argument(function_name<Query>(want_toi) +
                                  ": non-finite coordinate (NaN or infinity) in the query");
  if (!(std::isfinite(p.min_distance) && p.min_distance >= 0))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": min_distance must be finite and >= 0, not " +
                                shortest_text(p.min_distance));
  if (!(p.tmax > 0 && p.tmax <= 1))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": tmax must be in (0, 1], not " +
                                shortest_text(p.tmax));
  if (method != Method::filtered && method != Method::exact)
    throw std::invalid_argument(function_name<Query>(want_toi) + ": unknown method " +
                                std::to_string(static_cast<int>(method)));
}

/// The contact (d = 0) question of a query as an edge-edge query with the same answer and TOI:
/// a point is a zero-length edge, and a 2D query lies in the plane z = 0.
template <class Query>
EdgeEdgeQuery as_edge_edge(const Query& q) {
  constexpr int P = kinds::kind_of<Query>::points;
  const auto x = separation::points3<double>(q);  // 2D points at z = 0
  // Which point of the query each edge end is: (p, p) against (a, b) or (q, q).
  constexpr std::array<int, 4> ends = P == 4 ? std::array<int, 4>{0, 1, 2, 3}
                                      : P == 3 ? std::array<int, 4>{0, 0, 1, 2}
                                               : std::array<int, 4>{0, 0, 1, 1};
  std::array<Vec3, 8> e;
  for (int at = 0; at < 2; ++at)
    for (int i = 0; i < 4; ++i) e[at * 4 + i] = x[at * P + ends[i]];
  return from_rows<EdgeEdgeQuery>(e);
}

/// The contact filter for any kind.
template <class Query>
std::optional<TimeInterval> touch_filtered(const Query& q, bool want_toi, StageCounters* counters) {
  if constexpr (std::is_same_v<Query, VertexFaceQuery> || std::is_same_v<Query, EdgeEdgeQuery>)
    return filter::filtered(q, want_toi, counters);
  else
    return filter::filtered(as_edge_edge(q), want_toi, counters);
}

/// The TOI restricted to [0, tmax]: the exact time t lies in [lo, hi] (lo == hi, or lo < t < hi
/// with no double between them), so for a double tmax, t <= tmax iff hi <= tmax (or lo <= tmax
/// when lo == hi == t).
std::optional<TimeInterval> cut(const std::optional<TimeInterval>& t, double tmax) {
  if (!t) return t;
  const bool within = t->lo == t->hi ? t->lo <= tmax : t->hi <= tmax;
  return within ? t : std::nullopt;
}

template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& p, Method method, bool want_toi,
                                   StageCounters* counters) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  validate(q, p, method, want_toi);
  const bool whole_step = p.tmax == 1.0;
  constexpr bool touch_kind = std::is_same_v<Query, VertexFaceQuery> || std::is_same_v<Query, EdgeEdgeQuery>;
  if (p.min_distance == 0 && method == Method::filtered) {
    if constexpr (!touch_kind) {  // no volume filter for these: the separating direction first
      if (separation::separated_beyond(q, 0.0)) {
        if (counters) ++counters->separating_direction;
        return std::nullopt;
      }
    }
    return cut(touch_filtered(q, want_toi || !whole_step, counters), p.tmax);
  }
  if constexpr (touch_kind) {
    if (p.min_distance == 0) {  // Method::exact
      if (!want_toi && whole_step)
        return exact::ccd(exact::to_rational(q)) ? std::optional(TimeInterval{}) : std::nullopt;
      return cut(exact::toi(exact::to_rational(q)), p.tmax);
    }
  }
  if (method == Method::filtered) {
    if (separation::separated_beyond(q, p.min_distance)) {
      if (counters) ++counters->separating_direction;
      return std::nullopt;
    }
    // Whether the query collides: touching (distance 0) in [0, tmax] is being within d, and the
    // contact filter decides most touching pairs far more cheaply than the separation walk.
    // Its TOI t0 bounds the earliest time within d from above: [0, hi] encloses it.
    bool probe_used_gmp = false;
    if (!want_toi) {
      StageCounters probe;
      if (const auto touch = cut(touch_filtered(q, !whole_step, &probe), p.tmax)) {
        if (counters) *counters += probe;  // one query, counted at the contact stage deciding it
        return TimeInterval{0.0, touch->hi};
      }
      // Counted below, with the deciding stage; GMP or CGAL use (not the fixed-width integer
      // stage, which allocates nothing) makes it an `integer` query.
      probe_used_gmp = probe.integer + probe.exact > 0;
    }
    const separation::IntervalVerdict verdict = separation::interval_separation(q, p.min_distance, p.tmax, want_toi);
    if (verdict.decided) {
      if (counters) ++(verdict.used_integers || probe_used_gmp ? counters->integer : counters->interval);
      return verdict.toi;
    }
    if (counters) ++counters->exact;
    // The pairs a direction keeps apart hold nowhere: the exact path leaves them out.
    return separation::exact_toi(exact::to_rational(q), RationalCcdParams{mpq_class(p.min_distance), mpq_class(p.tmax)},
                                 verdict.use);
  }
  return separation::exact_toi(exact::to_rational(q), RationalCcdParams{mpq_class(p.min_distance), mpq_class(p.tmax)});
}

/// Throws std::invalid_argument naming the function on a negative d or a tmax outside (0, 1].
template <class Query>
void validate(const RationalCcdParams& p, bool want_toi) {
  if (!(p.min_distance >= 0))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": min_distance must be >= 0");
  if (!(p.tmax > 0 && p.tmax <= 1)) throw std::invalid_argument(function_name<Query>(want_toi) + ": tmax must be in (0, 1]");
}

template <class Query>
std::optional<TimeInterval> rational_answer(const Query& q, const RationalCcdParams& p, bool want_toi) {
  const filter::DefaultFpEnvironment fp_environment;  // CGAL's kernel filters with intervals
  validate<Query>(p, want_toi);
  using Kind = kinds::kind_of<Query>;
  if constexpr (std::is_same_v<Kind, kinds::VertexFace> || std::is_same_v<Kind, kinds::EdgeEdge>)
    if (p.min_distance == 0 && p.tmax == 1) return exact::toi(q);
  return separation::exact_toi(q, p);
}

}  // namespace

#define EXACTCCD_DEFINE_ENTRY_POINTS(Query, stem)                                                    \
  bool stem##_ccd(const Query& q, const CcdParams& p, Method m) {                                    \
    return answer(q, p, m, false, nullptr).has_value();                                              \
  }                                                                                                  \
  bool stem##_ccd(const Query& q, const CcdParams& p, Method m, StageCounters& c) {                  \
    return answer(q, p, m, false, &c).has_value();                                                   \
  }                                                                                                  \
  std::optional<TimeInterval> stem##_toi(const Query& q, const CcdParams& p, Method m) {             \
    return answer(q, p, m, true, nullptr);                                                           \
  }                                                                                                  \
  std::optional<TimeInterval> stem##_toi(const Query& q, const CcdParams& p, Method m, StageCounters& c) { \
    return answer(q, p, m, true, &c);                                                                \
  }
EXACTCCD_DEFINE_ENTRY_POINTS(VertexFaceQuery, vertex_face)
EXACTCCD_DEFINE_ENTRY_POINTS(EdgeEdgeQuery, edge_edge)
EXACTCCD_DEFINE_ENTRY_POINTS(PointEdgeQuery, point_edge)
EXACTCCD_DEFINE_ENTRY_POINTS(PointPointQuery, point_point)
EXACTCCD_DEFINE_ENTRY_POINTS(EdgeEdge2dQuery, edge_edge_2d)
EXACTCCD_DEFINE_ENTRY_POINTS(PointEdge2dQuery, point_edge_2d)
EXACTCCD_DEFINE_ENTRY_POINTS(PointPoint2dQuery, point_point_2d)
#undef EXACTCCD_DEFINE_ENTRY_POINTS

#define EXACTCCD_DEFINE_RATIONAL(Query)                                                               \
  bool ccd(const Query& q, const RationalCcdParams& p) { return rational_answer(q, p, false).has_value(); } \
  std::optional<TimeInterval> toi(const Query& q, const RationalCcdParams& p) { return rational_answer(q, p, true); }
EXACTCCD_DEFINE_RATIONAL(RationalVertexFaceQuery)
EXACTCCD_DEFINE_RATIONAL(RationalEdgeEdgeQuery)
EXACTCCD_DEFINE_RATIONAL(RationalPointEdgeQuery)
EXACTCCD_DEFINE_RATIONAL(RationalPointPointQuery)
EXACTCCD_DEFINE_RATIONAL(RationalEdgeEdge2dQuery)
EXACTCCD_DEFINE_RATIONAL(RationalPointEdge2dQuery)
EXACTCCD_DEFINE_RATIONAL(RationalPointPoint2dQuery)
#undef EXACTCCD_DEFINE_RATIONAL

}  // namespace exactccd
