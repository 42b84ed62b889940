// exactccd: exact continuous collision detection for linearly moving primitives.
// (Queries with rational coordinates: exactccd/rational.hpp, which needs GMP's headers.)
//
// The contract: for finite double or rational inputs every function answers as if computed
// in exact real arithmetic (except with Method::naive, the non-robust textbook baseline).
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
/// some t in [0, 1], decided exactly (unless method is Method::naive).
/// Throws std::invalid_argument on a non-finite coordinate.
bool vertex_face_ccd(const VertexFaceQuery& q, Method method = Method::filtered);

/// As above, and counts in `counters` which stage of the filtered method decided the query.
bool vertex_face_ccd(const VertexFaceQuery& q, Method method, StageCounters& counters);

/// True iff the moving closed segments (a0(t), a1(t)) and (b0(t), b1(t)) share a point for
/// some t in [0, 1], decided exactly (unless method is Method::naive).
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

}  // namespace exactccd
