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

#include <optional>

#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// True iff the moving point p(t) lies in the closed moving triangle (a(t), b(t), c(t)) for
/// some t in [0, 1], decided exactly.
/// Throws std::invalid_argument on a non-finite coordinate.
bool vertex_face_ccd(const VertexFaceQuery& q, Method method = Method::filtered);

/// As above, and counts in `counters` which stage of the filtered method decided the query.
bool vertex_face_ccd(const VertexFaceQuery& q, Method method, StageCounters& counters);

/// True iff the moving closed segments (a0(t), a1(t)) and (b0(t), b1(t)) share a point for
/// some t in [0, 1], decided exactly.
/// Throws std::invalid_argument on a non-finite coordinate.
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method = Method::filtered);

/// As above, and counts in `counters` which stage of the filtered method decided the query.
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method, StageCounters& counters);

/// Earliest time of impact of a vertex-face query: the smallest t in [0, 1] at which p(t) is
/// in the closed triangle, enclosed in the tightest double interval [lo, hi] (lo == hi when
/// that time is a double, hi == nextafter(lo, +inf) otherwise), or std::nullopt when the
/// primitives never touch. Throws std::invalid_argument on a non-finite coordinate.
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q,
                                            Method method = Method::filtered);

/// As above, and counts in `counters` which stage decided the query.
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method,
                                            StageCounters& counters);

/// Earliest time of impact of an edge-edge query; see vertex_face_toi.
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q,
                                          Method method = Method::filtered);

/// As above, and counts in `counters` which stage decided the query.
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method,
                                          StageCounters& counters);

/// Overloads on the query type, for code that handles every kind alike (templates): the same
/// functions as vertex_face_ccd / edge_edge_ccd and vertex_face_toi / edge_edge_toi.
inline bool ccd(const VertexFaceQuery& q, Method method = Method::filtered) { return vertex_face_ccd(q, method); }
/// See ccd(const VertexFaceQuery&, Method).
inline bool ccd(const EdgeEdgeQuery& q, Method method = Method::filtered) { return edge_edge_ccd(q, method); }
/// See ccd(const VertexFaceQuery&, Method), with statistics.
inline bool ccd(const VertexFaceQuery& q, Method method, StageCounters& counters) {
  return vertex_face_ccd(q, method, counters);
}
/// See ccd(const VertexFaceQuery&, Method), with statistics.
inline bool ccd(const EdgeEdgeQuery& q, Method method, StageCounters& counters) {
  return edge_edge_ccd(q, method, counters);
}
/// The TOI of a query of either kind; see ccd(const VertexFaceQuery&, Method).
inline std::optional<TimeInterval> toi(const VertexFaceQuery& q, Method method = Method::filtered) {
  return vertex_face_toi(q, method);
}
/// See toi(const VertexFaceQuery&, Method).
inline std::optional<TimeInterval> toi(const EdgeEdgeQuery& q, Method method = Method::filtered) {
  return edge_edge_toi(q, method);
}
/// See toi(const VertexFaceQuery&, Method), with statistics.
inline std::optional<TimeInterval> toi(const VertexFaceQuery& q, Method method, StageCounters& counters) {
  return vertex_face_toi(q, method, counters);
}
/// See toi(const VertexFaceQuery&, Method), with statistics.
inline std::optional<TimeInterval> toi(const EdgeEdgeQuery& q, Method method, StageCounters& counters) {
  return edge_edge_toi(q, method, counters);
}

// ---------------------------------------------------------------------------------------
// Minimum separation and a time limit (CcdParams), and every primitive kind.
//
// For finite coordinates, params.min_distance = d (finite, >= 0) and params.tmax in (0, 1]:
// a query collides iff some t in [0, tmax] has dist(A(t), B(t)) <= d, with dist the Euclidean
// distance between the closed primitives (a degenerate triangle or a zero-length edge is its
// hull); its TOI is the earliest such t, as the tightest double interval ([0, 0] when the
// initial distance is <= d). CcdParams{} (d = 0, tmax = 1) gives exactly the answers and TOIs
// of the functions above. Throws std::invalid_argument on a non-finite coordinate, a negative
// or non-finite d, a tmax outside (0, 1], or a value that is not a Method.
// 2D kinds: the same questions in the plane (their answers equal those of the 3D kind with
// every z = 0).
// ---------------------------------------------------------------------------------------

/// Vertex-face with a minimum separation and a time limit.
bool vertex_face_ccd(const VertexFaceQuery& q, const CcdParams& params, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool vertex_face_ccd(const VertexFaceQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest t in [0, tmax] with dist(p(t), triangle(t)) <= d, or nullopt.
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, const CcdParams& params,
                                            Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, const CcdParams& params, Method method,
                                            StageCounters& counters);

/// Edge-edge with a minimum separation and a time limit.
bool edge_edge_ccd(const EdgeEdgeQuery& q, const CcdParams& params, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool edge_edge_ccd(const EdgeEdgeQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest t in [0, tmax] with dist(edge a(t), edge b(t)) <= d, or nullopt.
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, const CcdParams& params,
                                          Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, const CcdParams& params, Method method,
                                          StageCounters& counters);

/// Point-edge: true iff dist(p(t), segment [a(t), b(t)]) <= d for some t in [0, tmax].
bool point_edge_ccd(const PointEdgeQuery& q, const CcdParams& params = {}, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool point_edge_ccd(const PointEdgeQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest such t, or nullopt.
std::optional<TimeInterval> point_edge_toi(const PointEdgeQuery& q, const CcdParams& params = {},
                                           Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> point_edge_toi(const PointEdgeQuery& q, const CcdParams& params, Method method,
                                           StageCounters& counters);

/// Point-point: true iff |p(t) - q(t)| <= d for some t in [0, tmax].
bool point_point_ccd(const PointPointQuery& q, const CcdParams& params = {}, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool point_point_ccd(const PointPointQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest such t, or nullopt.
std::optional<TimeInterval> point_point_toi(const PointPointQuery& q, const CcdParams& params = {},
                                            Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> point_point_toi(const PointPointQuery& q, const CcdParams& params, Method method,
                                            StageCounters& counters);

/// Edge-edge in the plane.
bool edge_edge_2d_ccd(const EdgeEdge2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool edge_edge_2d_ccd(const EdgeEdge2dQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest contact time of an edge-edge query in the plane, or nullopt.
std::optional<TimeInterval> edge_edge_2d_toi(const EdgeEdge2dQuery& q, const CcdParams& params = {},
                                             Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> edge_edge_2d_toi(const EdgeEdge2dQuery& q, const CcdParams& params, Method method,
                                             StageCounters& counters);

/// Point-edge in the plane.
bool point_edge_2d_ccd(const PointEdge2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool point_edge_2d_ccd(const PointEdge2dQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest contact time of a point-edge query in the plane, or nullopt.
std::optional<TimeInterval> point_edge_2d_toi(const PointEdge2dQuery& q, const CcdParams& params = {},
                                              Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> point_edge_2d_toi(const PointEdge2dQuery& q, const CcdParams& params, Method method,
                                              StageCounters& counters);

/// Point-point in the plane.
bool point_point_2d_ccd(const PointPoint2dQuery& q, const CcdParams& params = {}, Method method = Method::filtered);
/// As above, counting the deciding stage.
bool point_point_2d_ccd(const PointPoint2dQuery& q, const CcdParams& params, Method method, StageCounters& counters);
/// Earliest contact time of a point-point query in the plane, or nullopt.
std::optional<TimeInterval> point_point_2d_toi(const PointPoint2dQuery& q, const CcdParams& params = {},
                                               Method method = Method::filtered);
/// As above, counting the deciding stage.
std::optional<TimeInterval> point_point_2d_toi(const PointPoint2dQuery& q, const CcdParams& params, Method method,
                                               StageCounters& counters);

#define EXACTCCD_GENERIC_OVERLOADS(Query, stem)                                                      \
  /** The answer for a query of this kind: see stem##_ccd. */                                        \
  inline bool ccd(const Query& q, const CcdParams& params, Method method = Method::filtered) {       \
    return stem##_ccd(q, params, method);                                                            \
  }                                                                                                  \
  /** See stem##_ccd, with statistics. */                                                            \
  inline bool ccd(const Query& q, const CcdParams& params, Method method, StageCounters& counters) { \
    return stem##_ccd(q, params, method, counters);                                                  \
  }                                                                                                  \
  /** The TOI of a query of this kind: see stem##_toi. */                                            \
  inline std::optional<TimeInterval> toi(const Query& q, const CcdParams& params,                    \
                                         Method method = Method::filtered) {                         \
    return stem##_toi(q, params, method);                                                            \
  }                                                                                                  \
  /** See stem##_toi, with statistics. */                                                            \
  inline std::optional<TimeInterval> toi(const Query& q, const CcdParams& params, Method method,     \
                                         StageCounters& counters) {                                  \
    return stem##_toi(q, params, method, counters);                                                  \
  }
EXACTCCD_GENERIC_OVERLOADS(VertexFaceQuery, vertex_face)
EXACTCCD_GENERIC_OVERLOADS(EdgeEdgeQuery, edge_edge)
EXACTCCD_GENERIC_OVERLOADS(PointEdgeQuery, point_edge)
EXACTCCD_GENERIC_OVERLOADS(PointPointQuery, point_point)
EXACTCCD_GENERIC_OVERLOADS(EdgeEdge2dQuery, edge_edge_2d)
EXACTCCD_GENERIC_OVERLOADS(PointEdge2dQuery, point_edge_2d)
EXACTCCD_GENERIC_OVERLOADS(PointPoint2dQuery, point_point_2d)
#undef EXACTCCD_GENERIC_OVERLOADS

}  // namespace exactccd
