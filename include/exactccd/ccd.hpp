// exactccd: exact continuous collision detection for linearly moving primitives.
// (Queries with rational coordinates: exactccd/rational.hpp, which needs GMP's headers.)
//
// The contract: for finite double or rational inputs every function answers as if computed
// in exact real arithmetic, by either method (Method::filtered, the default, or Method::exact).
// - Vertex-face collides iff some t in [0,1] puts p(t) in the closed convex hull of
//   a(t), b(t), c(t) (a degenerate triangle is a segment or a point).
// - Edge-edge collides iff some t in [0,1] gives the closed segments a common point
//   (a zero-length edge is a point).
// The time of impact (TOI) is the earliest such t, returned as a certified double interval.
//
// All functions are thread-safe: they share no mutable state. They give the same answers in
// any floating-point environment of the calling thread (any rounding direction, flush-to-zero
// or denormals-are-zero, unmasked exceptions): each call installs the default environment
// for its duration and restores the caller's on return, also when it throws.
#pragma once

#include <cstddef>
#include <optional>
#include <type_traits>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

// ---------------------------------------------------------------------------------------
// The one entry point, and the question it answers.
//
// For finite coordinates, params.min_distance = d (finite, >= 0) and params.tmax in (0, 1]:
// a query collides iff some t in [0, tmax] has dist(A(t), B(t)) <= d, with dist the Euclidean
// distance between the closed primitives (a degenerate triangle or a zero-length edge is its
// hull); its TOI is the earliest such t, as the tightest double interval ([0, 0] when the
// initial distance is <= d). CcdParams{} (d = 0, tmax = 1) asks whether the primitives touch
// during the step. 2D kinds: the same questions in the plane (their answers equal those of the
// 3D kind with every z = 0).
// ---------------------------------------------------------------------------------------

/// The one function behind every other of this header: the answer to `params` for a query of
/// any kind (the query types of types.hpp; the library defines it for each) by `method`. Returns
/// the TOI when `want_toi` (else, for a collision, the interval [0, 0]: only its presence
/// matters) or nullopt for no collision, and counts in `counters` (may be null) which stage of
/// the filtered method decided. Installs the default floating-point environment for the call.
/// Throws std::invalid_argument on a non-finite coordinate, a negative or non-finite
/// min_distance, a tmax outside (0, 1], or a value that is not a Method.
template <class Query>
std::optional<TimeInterval> answer_query(const Query& q, const CcdParams& params, Method method, bool want_toi,
                                         StageCounters* counters);

/// The answers to one question for `count` queries of one kind (the double query types of
/// types.hpp): answers[i] is what answer_query(queries[i], params, method, want_toi, counters)
/// returns, for every i < count, counted in `counters` (may be null). The filtered method runs
/// each question's stage list on blocks of queries (its stages with a block form in vector
/// lanes: docs/architecture.md, "The block protocol"); the answers are the same. Checks the
/// parameters and every query before answering any: throws std::invalid_argument as
/// answer_query does, naming the first bad query's index. Installs the default floating-point
/// environment for the call.
template <class Query>
void answer_batch(const Query* queries, std::size_t count, const CcdParams& params, Method method, bool want_toi,
                  std::optional<TimeInterval>* answers, StageCounters* counters = nullptr);

/// True for the query types with double coordinates (the kinds of types.hpp).
template <class Query>
inline constexpr bool is_double_query = std::is_same_v<coordinate_t<Query>, double>;

/// Whether a query of any kind collides: true iff the primitives come within
/// params.min_distance of each other at some t in [0, params.tmax]. The named functions below
/// (vertex_face_ccd, point_edge_ccd, ...) are the same for one kind each.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
bool ccd(const Query& q, const CcdParams& params, Method method = Method::filtered) {
  return answer_query(q, params, method, false, nullptr).has_value();
}
/// As ccd(q, params, method), counting in `counters` which stage decided.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
bool ccd(const Query& q, const CcdParams& params, Method method, StageCounters& counters) {
  return answer_query(q, params, method, false, &counters).has_value();
}
/// Whether a query of any kind's primitives touch during the step (CcdParams{}).
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
bool ccd(const Query& q, Method method = Method::filtered) {
  return answer_query(q, CcdParams{}, method, false, nullptr).has_value();
}
/// As ccd(q, method), counting in `counters` which stage decided.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
bool ccd(const Query& q, Method method, StageCounters& counters) {
  return answer_query(q, CcdParams{}, method, false, &counters).has_value();
}

/// The earliest t in [0, params.tmax] at which a query of any kind's primitives are within
/// params.min_distance, in the tightest double interval [lo, hi] (lo == hi when that time is a
/// double, hi == nextafter(lo, +inf) otherwise), or nullopt when they never are.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
std::optional<TimeInterval> toi(const Query& q, const CcdParams& params, Method method = Method::filtered) {
  return answer_query(q, params, method, true, nullptr);
}
/// As toi(q, params, method), counting in `counters` which stage decided.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
std::optional<TimeInterval> toi(const Query& q, const CcdParams& params, Method method, StageCounters& counters) {
  return answer_query(q, params, method, true, &counters);
}
/// The earliest time of contact of a query of any kind in [0, 1] (CcdParams{}), or nullopt.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
std::optional<TimeInterval> toi(const Query& q, Method method = Method::filtered) {
  return answer_query(q, CcdParams{}, method, true, nullptr);
}
/// As toi(q, method), counting in `counters` which stage decided.
template <class Query, std::enable_if_t<is_double_query<Query>, int> = 0>
std::optional<TimeInterval> toi(const Query& q, Method method, StageCounters& counters) {
  return answer_query(q, CcdParams{}, method, true, &counters);
}

// ---------------------------------------------------------------------------------------
// The named functions of each kind (the same as ccd() and toi() above).
// ---------------------------------------------------------------------------------------

/// True iff the moving point p(t) lies in the closed moving triangle (a(t), b(t), c(t)) for
/// some t in [0, 1], decided exactly. Throws std::invalid_argument on a non-finite coordinate.
inline bool vertex_face_ccd(const VertexFaceQuery& q, Method method = Method::filtered) { return ccd(q, method); }
/// As above, and counts in `counters` which stage of the filtered method decided the query.
inline bool vertex_face_ccd(const VertexFaceQuery& q, Method method, StageCounters& counters) { return ccd(q, method, counters); }
/// Vertex-face with a minimum separation and a time limit.
inline bool vertex_face_ccd(const VertexFaceQuery& q, const CcdParams& params, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool vertex_face_ccd(const VertexFaceQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest time of impact of a vertex-face query: the smallest t in [0, 1] at which p(t) is in
/// the closed triangle, enclosed in the tightest double interval [lo, hi], or std::nullopt when
/// the primitives never touch. Throws std::invalid_argument on a non-finite coordinate.
inline std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method = Method::filtered) {
  return toi(q, method);
}
/// As above, and counts in `counters` which stage decided the query.
inline std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method, StageCounters& counters) {
  return toi(q, method, counters);
}
/// Earliest t in [0, tmax] with dist(p(t), triangle(t)) <= d, or nullopt.
inline std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, const CcdParams& params,
                                                   Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, const CcdParams& params, Method method,
                                                   StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// True iff the moving closed segments (a0(t), a1(t)) and (b0(t), b1(t)) share a point for
/// some t in [0, 1], decided exactly. Throws std::invalid_argument on a non-finite coordinate.
inline bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method = Method::filtered) { return ccd(q, method); }
/// As above, and counts in `counters` which stage of the filtered method decided the query.
inline bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method, StageCounters& counters) { return ccd(q, method, counters); }
/// Edge-edge with a minimum separation and a time limit.
inline bool edge_edge_ccd(const EdgeEdgeQuery& q, const CcdParams& params, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool edge_edge_ccd(const EdgeEdgeQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest time of impact of an edge-edge query; see vertex_face_toi.
inline std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method = Method::filtered) {
  return toi(q, method);
}
/// As above, and counts in `counters` which stage decided the query.
inline std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method, StageCounters& counters) {
  return toi(q, method, counters);
}
/// Earliest t in [0, tmax] with dist(edge a(t), edge b(t)) <= d, or nullopt.
inline std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, const CcdParams& params,
                                                 Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, const CcdParams& params, Method method,
                                                 StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// Point-edge: true iff dist(p(t), segment [a(t), b(t)]) <= d for some t in [0, tmax].
inline bool point_edge_ccd(const PointEdgeQuery& q, const CcdParams& params = {}, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool point_edge_ccd(const PointEdgeQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest such t, or nullopt.
inline std::optional<TimeInterval> point_edge_toi(const PointEdgeQuery& q, const CcdParams& params = {},
                                                  Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> point_edge_toi(const PointEdgeQuery& q, const CcdParams& params, Method method,
                                                  StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// Point-point: true iff |p(t) - q(t)| <= d for some t in [0, tmax].
inline bool point_point_ccd(const PointPointQuery& q, const CcdParams& params = {}, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool point_point_ccd(const PointPointQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest such t, or nullopt.
inline std::optional<TimeInterval> point_point_toi(const PointPointQuery& q, const CcdParams& params = {},
                                                   Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> point_point_toi(const PointPointQuery& q, const CcdParams& params, Method method,
                                                   StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// Edge-edge in the plane.
inline bool edge_edge_2d_ccd(const EdgeEdge2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool edge_edge_2d_ccd(const EdgeEdge2dQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest contact time of an edge-edge query in the plane, or nullopt.
inline std::optional<TimeInterval> edge_edge_2d_toi(const EdgeEdge2dQuery& q, const CcdParams& params = {},
                                                    Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> edge_edge_2d_toi(const EdgeEdge2dQuery& q, const CcdParams& params, Method method,
                                                    StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// Point-edge in the plane.
inline bool point_edge_2d_ccd(const PointEdge2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool point_edge_2d_ccd(const PointEdge2dQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest contact time of a point-edge query in the plane, or nullopt.
inline std::optional<TimeInterval> point_edge_2d_toi(const PointEdge2dQuery& q, const CcdParams& params = {},
                                                     Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> point_edge_2d_toi(const PointEdge2dQuery& q, const CcdParams& params, Method method,
                                                     StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// Point-point in the plane.
inline bool point_point_2d_ccd(const PointPoint2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool point_point_2d_ccd(const PointPoint2dQuery& q, const CcdParams& params, Method method, StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// Earliest contact time of a point-point query in the plane, or nullopt.
inline std::optional<TimeInterval> point_point_2d_toi(const PointPoint2dQuery& q, const CcdParams& params = {},
                                                      Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> point_point_2d_toi(const PointPoint2dQuery& q, const CcdParams& params, Method method,
                                                      StageCounters& counters) {
  return toi(q, params, method, counters);
}

}  // namespace exactccd
