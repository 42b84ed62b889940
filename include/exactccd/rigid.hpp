// exactccd: exact continuous collision detection for rigidly moving bodies (rotation and
// translation over the step).
//
// The motion (docs/design.md, section 9). A body's pose is a translation c and a rotation given
// by a quaternion q = (w, x, y, z), not all zero and of any length: the rotation matrix is
// R(q) = M(q) / |q|^2 with
//   M = [[w²+x²−y²−z², 2(xy−wz), 2(xz+wy)], [2(xy+wz), w²−x²+y²−z², 2(yz−wx)],
//        [2(xz−wy), 2(yz+wx), w²−x²−y²+z²]],
// and a body point p (body coordinates) is at X = c + R(q) p. Over the step the pose moves from
// (c0, q0) to (c1, q1) along c(t) = (1 − t) c0 + t c1, q(t) = (1 − t) q0 + t q1: a rotation about
// one fixed axis by a monotone angle (the short arc when q0 · q1 > 0; the caller chooses the
// sign of q1). Every position is then a rational function of t, and the question is decided
// exactly: a query collides iff some t in [0, tmax] has Euclidean distance <= d = min_distance
// between the closed primitives (a degenerate triangle or a zero-length edge is its hull); its
// time of impact (TOI) is the earliest such t, as the tightest double interval [lo, hi].
// A static body is the identity motion (c1 = c0, q1 = q0).
//
// Bad input is never answered: every function throws std::invalid_argument on a non-finite
// number, on a d that is negative or not finite, a tmax outside (0, 1], and on a quaternion path
// that vanishes somewhere in [0, 1] (q0 = 0, q1 = 0, or q1 a negative multiple of q0), decided
// exactly.
//
// All functions are thread-safe and give the same answers in any floating-point environment of
// the calling thread (as those of ccd.hpp).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/scene.hpp"
#include "exactccd/stats.hpp"
#include "exactccd/types.hpp"

namespace exactccd {

/// A quaternion (w, x, y, z) of number type T: w is the scalar part. Need not have unit length.
template <class T>
struct QuaternionT {
  T w;  ///< scalar part
  T x;  ///< first vector component
  T y;  ///< second vector component
  T z;  ///< third vector component
};

using Quaternion = QuaternionT<double>;  ///< double components

/// A rigid body's pose: the point of world space where its body origin is, and its rotation.
template <class T>
struct RigidPoseT {
  Vec3T<T> c;         ///< translation: the body origin in world coordinates
  QuaternionT<T> q;   ///< rotation R(q) = M(q) / |q|^2 (q not zero)
};

using RigidPose = RigidPoseT<double>;  ///< double components

/// A rigid vertex-face query: a vertex p of body A against the triangle (a, b, c) of body B,
/// points in body coordinates, each body moving from its pose at t = 0 to its pose at t = 1.
/// Member order is the order of the CLI's 41-number lines.
template <class T>
struct RigidVertexFaceQueryT {
  RigidPoseT<T> a_t0;  ///< body A's pose at t = 0
  RigidPoseT<T> a_t1;  ///< body A's pose at t = 1
  RigidPoseT<T> b_t0;  ///< body B's pose at t = 0
  RigidPoseT<T> b_t1;  ///< body B's pose at t = 1
  Vec3T<T> p;          ///< the vertex, in A's body coordinates
  Vec3T<T> a;          ///< the triangle's first vertex, in B's body coordinates
  Vec3T<T> b;          ///< the triangle's second vertex, in B's body coordinates
  Vec3T<T> c;          ///< the triangle's third vertex, in B's body coordinates
};

/// A rigid edge-edge query: the edge (a0, a1) of body A against the edge (b0, b1) of body B.
template <class T>
struct RigidEdgeEdgeQueryT {
  RigidPoseT<T> a_t0;  ///< body A's pose at t = 0
  RigidPoseT<T> a_t1;  ///< body A's pose at t = 1
  RigidPoseT<T> b_t0;  ///< body B's pose at t = 0
  RigidPoseT<T> b_t1;  ///< body B's pose at t = 1
  Vec3T<T> a0;         ///< first end of A's edge, in A's body coordinates
  Vec3T<T> a1;         ///< second end of A's edge, in A's body coordinates
  Vec3T<T> b0;         ///< first end of B's edge, in B's body coordinates
  Vec3T<T> b1;         ///< second end of B's edge, in B's body coordinates
};

using RigidVertexFaceQuery = RigidVertexFaceQueryT<double>;  ///< double components
using RigidEdgeEdgeQuery = RigidEdgeEdgeQueryT<double>;      ///< double components

/// The body points of a query in the order of its kind (vertex-face: p, a, b, c; edge-edge:
/// a0, a1, b0, b1): the first one (vertex-face) or two (edge-edge) are body A's.
template <class T>
std::array<Vec3T<T>, 4> body_points(const RigidVertexFaceQueryT<T>& q) {
  return {q.p, q.a, q.b, q.c};
}
/// See body_points(const RigidVertexFaceQueryT<T>&).
template <class T>
std::array<Vec3T<T>, 4> body_points(const RigidEdgeEdgeQueryT<T>& q) {
  return {q.a0, q.a1, q.b0, q.b1};
}

/// The coordinate type of a rigid query (for ccd.hpp's ccd() and toi(), which therefore take
/// rigid queries too).
template <class T>
struct QueryCoordinate<RigidVertexFaceQueryT<T>> {
  using type = T;  ///< double, or mpq_class inside the library
};
/// See QueryCoordinate<RigidVertexFaceQueryT<T>>.
template <class T>
struct QueryCoordinate<RigidEdgeEdgeQueryT<T>> {
  using type = T;  ///< double, or mpq_class inside the library
};

/// The one entry point (ccd.hpp) for rigid vertex-face queries: their answer to `params` by
/// `method`, the TOI when `want_toi`. Throws std::invalid_argument on bad input (the top of this
/// file) or an unknown method. ccd(), toi() and the named functions below call it.
template <>
std::optional<TimeInterval> answer_query(const RigidVertexFaceQuery& q, const CcdParams& params, Method method,
                                         bool want_toi, StageCounters* counters);
/// The one entry point for rigid edge-edge queries; see answer_query(const RigidVertexFaceQuery&, ...).
template <>
std::optional<TimeInterval> answer_query(const RigidEdgeEdgeQuery& q, const CcdParams& params, Method method,
                                         bool want_toi, StageCounters* counters);

/// True iff a rigid vertex-face query collides: p comes within distance <= params.min_distance
/// of the closed triangle at some t in [0, params.tmax], decided exactly. Throws
/// std::invalid_argument on bad input (see the top of this file) or an unknown method.
inline bool rigid_vertex_face_ccd(const RigidVertexFaceQuery& q, const CcdParams& params = {},
                                  Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting in `counters` which stage of the filtered method decided the query.
inline bool rigid_vertex_face_ccd(const RigidVertexFaceQuery& q, const CcdParams& params, Method method,
                                  StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// The earliest t in [0, tmax] at which p is within distance <= d of the triangle, as the
/// tightest double interval, or std::nullopt when there is none.
inline std::optional<TimeInterval> rigid_vertex_face_toi(const RigidVertexFaceQuery& q, const CcdParams& params = {},
                                                         Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> rigid_vertex_face_toi(const RigidVertexFaceQuery& q, const CcdParams& params,
                                                         Method method, StageCounters& counters) {
  return toi(q, params, method, counters);
}

/// True iff a rigid edge-edge query collides: the closed edges come within distance <=
/// params.min_distance of each other at some t in [0, params.tmax], decided exactly.
inline bool rigid_edge_edge_ccd(const RigidEdgeEdgeQuery& q, const CcdParams& params = {},
                                Method method = Method::filtered) {
  return ccd(q, params, method);
}
/// As above, counting the deciding stage.
inline bool rigid_edge_edge_ccd(const RigidEdgeEdgeQuery& q, const CcdParams& params, Method method,
                                StageCounters& counters) {
  return ccd(q, params, method, counters);
}
/// The earliest t in [0, tmax] at which the edges are within distance <= d, or std::nullopt.
inline std::optional<TimeInterval> rigid_edge_edge_toi(const RigidEdgeEdgeQuery& q, const CcdParams& params = {},
                                                       Method method = Method::filtered) {
  return toi(q, params, method);
}
/// As above, counting the deciding stage.
inline std::optional<TimeInterval> rigid_edge_edge_toi(const RigidEdgeEdgeQuery& q, const CcdParams& params,
                                                       Method method, StageCounters& counters) {
  return toi(q, params, method, counters);
}

// ---------------------------------------------------------------------------------------
// Scenes of rigid bodies over one step.
//
// Each body is a triangle mesh in body coordinates with its poses at t = 0 and t = 1 (moving as
// above). Its primitives: the vertices its triangles reference, their unique edges, its
// triangles. The pairs are between different bodies: a vertex of one body against a triangle
// of another (vertex-face, in both directions), an edge of one against an edge of a later one
// (edge-edge); pairs within one body are never tested (a rigid body keeps its shape). Each is
// decided exactly as rigid_vertex_face_toi / rigid_edge_edge_toi decide it with
// CcdParams{options.min_distance, options.tmax}, after a broad phase of certified swept boxes
// (every vertex's box over the step holds its exact curve, grown by d; docs/design.md 9.5),
// which drops only pairs that cannot come within d. For d > 0 the vertex-face and edge-edge
// pairs cover the distance between two triangle meshes (the closest points of two closed
// triangles are a vertex and a face, or two edges).
// ---------------------------------------------------------------------------------------

/// A rigid body over one step: a triangle mesh in body coordinates and its two poses.
struct RigidBody {
  std::vector<Vec3> vertices;                 ///< body coordinates
  std::vector<std::array<int, 3>> triangles;  ///< three distinct vertex indices each
  RigidPose t0;                               ///< the pose at t = 0
  RigidPose t1;                               ///< the pose at t = 1
};

/// A colliding pair between two bodies and its time of impact.
struct RigidCollision {
  CollisionKind kind = CollisionKind::vertex_face;  ///< vertex_face or edge_edge
  int body_a = -1;  ///< vertex-face: the vertex's body; edge-edge: the first edge's body (body_a < body_b)
  int body_b = -1;  ///< vertex-face: the triangle's body; edge-edge: the second edge's body
  int vertex = -1;    ///< vertex-face: the vertex, an index into body_a's vertices
  int triangle = -1;  ///< vertex-face: the triangle, an index into body_b's triangles
  std::array<int, 2> edge_a{{-1, -1}};  ///< edge-edge: body_a's edge (ascending vertex indices)
  std::array<int, 2> edge_b{{-1, -1}};  ///< edge-edge: body_b's edge (ascending vertex indices)
  TimeInterval toi;  ///< tightest double enclosure of the pair's earliest time within d
};

/// Throws std::invalid_argument, naming the body and the element, when a body is malformed: a
/// coordinate or pose component not finite, a triangle index out of range or repeated, or a
/// quaternion path that vanishes in [0, 1].
void validate(const std::vector<RigidBody>& bodies);

/// Every colliding pair (vertex-face first, by (body_a, vertex, body_b, triangle); then edge-edge
/// by (body_a, body_b, edge_a, edge_b)) with its TOI, for CcdParams{options.min_distance,
/// options.tmax}; on options.threads threads (the result does not depend on them). Throws
/// std::invalid_argument on a malformed body (validate) or invalid options; exactccd::Cancelled
/// when options.cancel is set during the call (as the linear scene functions of scene.hpp).
std::vector<RigidCollision> rigid_find_collisions(const std::vector<RigidBody>& bodies, const SceneOptions& options = {});

/// The earliest time of impact over every pair (the tightest double interval), or nullopt.
std::optional<TimeInterval> rigid_earliest_toi(const std::vector<RigidBody>& bodies, const SceneOptions& options = {});

/// The largest step s <= tmax over which no pair comes within d: tmax without a collision, else
/// the largest double below the earliest time of impact's lo (0 for a collision at t = 0), as
/// max_collision_free_step of scene.hpp.
double rigid_max_collision_free_step(const std::vector<RigidBody>& bodies, const SceneOptions& options = {});

}  // namespace exactccd
