// The named polynomials in t whose signs decide contact (docs/design.md, "The contact rule").
//
// Written once, templated on the coefficient type NT: mpq_class for the exact path,
// intervals or doubles for the filters. Each query's polynomials are built once; the rule in
// contact_rule.hpp only asks for their signs at a time t.
#pragma once

#include <array>

#include "contact/polynomial.hpp"
#include "contact/vec3_ops.hpp"
#include "exactccd/types.hpp"

namespace exactccd::contact {

template <class NT, int D>
using PolyVec3 = Vec3T<Poly<NT, D>>;

/// Polynomials deciding "q(t) lies on the closed segment [u(t), v(t)]":
/// cross = (q - u) x (v - u) vanishes (q on the line, or u == v), and
/// dot = (q - u) . (v - q) >= 0 (q between u and v; with u == v it forces q == u).
template <class NT>
struct PointOnSegmentPolys {
  PolyVec3<NT, 2> cross;
  Poly<NT, 2> dot;
};

/// Vertex-face polynomials of p against triangle (a, b, c).
template <class NT>
struct VertexFacePolys {
  Poly<NT, 3> volume;                           ///< V = (b - a) . ((c - a) x (p - a))
  PolyVec3<NT, 2> normal;                       ///< n = (b - a) x (c - a)
  std::array<Poly<NT, 4>, 3> barycentric;       ///< n . (e_i x (p - v_i)), edges ab, bc, ca
  std::array<PointOnSegmentPolys<NT>, 3> on_edge;  ///< p on ab, bc, ca
};

/// Edge-edge polynomials of segment (a0, a1) against segment (b0, b1).
/// With da = a1 - a0, db = b1 - b0, r = b0 - a0, w = da x db, D = w . w, the coplanar lines
/// meet at a0 + (U / D) da = b0 + (W / D) db where U = (r x db) . w and W = (r x da) . w.
template <class NT>
struct EdgeEdgePolys {
  Poly<NT, 3> volume;                     ///< V = da . (r x (b1 - a0))
  PolyVec3<NT, 2> direction_cross;        ///< w = da x db
  std::array<Poly<NT, 4>, 4> parameters;  ///< U, D - U, W, D - W (all >= 0: alpha, beta in [0,1])
  std::array<PointOnSegmentPolys<NT>, 4> endpoint_on_edge;  ///< a0, a1 on b; b0, b1 on a
};

/// The linear motion of a point from its position at t = 0 to its position at t = 1.
template <class NT>
PolyVec3<NT, 1> point_motion(const Vec3T<NT>& x0, const Vec3T<NT>& x1) {
  return {linear_motion(x0.x, x1.x), linear_motion(x0.y, x1.y), linear_motion(x0.z, x1.z)};
}

template <class NT>
PointOnSegmentPolys<NT> point_on_segment_polys(const PolyVec3<NT, 1>& q, const PolyVec3<NT, 1>& u,
                                               const PolyVec3<NT, 1>& v) {
  return {cross(q - u, v - u), dot(q - u, v - q)};
}

/// The vertex-face volume V(t) = (b - a) . ((c - a) x (p - a)) alone (the cheap first test).
template <class NT>
Poly<NT, 3> vertex_face_volume(const VertexFaceQueryT<NT>& q) {
  const auto p = point_motion(q.p_t0, q.p_t1);
  const auto a = point_motion(q.a_t0, q.a_t1);
  const auto b = point_motion(q.b_t0, q.b_t1);
  const auto c = point_motion(q.c_t0, q.c_t1);
  return dot(b - a, cross(c - a, p - a));
}

/// The edge-edge volume V(t) = (a1 - a0) . ((b0 - a0) x (b1 - a0)) alone.
template <class NT>
Poly<NT, 3> edge_edge_volume(const EdgeEdgeQueryT<NT>& q) {
  const auto a0 = point_motion(q.a0_t0, q.a0_t1);
  const auto a1 = point_motion(q.a1_t0, q.a1_t1);
  const auto b0 = point_motion(q.b0_t0, q.b0_t1);
  const auto b1 = point_motion(q.b1_t0, q.b1_t1);
  return dot(a1 - a0, cross(b0 - a0, b1 - a0));
}

/// Builds the vertex-face polynomials of a query whose coordinates are of type NT.
template <class NT>
VertexFacePolys<NT> vertex_face_polys(const VertexFaceQueryT<NT>& q) {
  const auto p = point_motion(q.p_t0, q.p_t1);
  const auto a = point_motion(q.a_t0, q.a_t1);
  const auto b = point_motion(q.b_t0, q.b_t1);
  const auto c = point_motion(q.c_t0, q.c_t1);
  VertexFacePolys<NT> r;
  r.normal = cross(b - a, c - a);
  r.volume = vertex_face_volume(q);
  r.barycentric = {dot(r.normal, cross(b - a, p - a)), dot(r.normal, cross(c - b, p - b)),
                   dot(r.normal, cross(a - c, p - c))};
  r.on_edge = {point_on_segment_polys(p, a, b), point_on_segment_polys(p, b, c),
               point_on_segment_polys(p, c, a)};
  return r;
}

/// Builds the edge-edge polynomials of a query whose coordinates are of type NT.
template <class NT>
EdgeEdgePolys<NT> edge_edge_polys(const EdgeEdgeQueryT<NT>& q) {
  const auto a0 = point_motion(q.a0_t0, q.a0_t1);
  const auto a1 = point_motion(q.a1_t0, q.a1_t1);
  const auto b0 = point_motion(q.b0_t0, q.b0_t1);
  const auto b1 = point_motion(q.b1_t0, q.b1_t1);
  const auto da = a1 - a0;
  const auto db = b1 - b0;
  const auto r = b0 - a0;
  EdgeEdgePolys<NT> e;
  e.volume = edge_edge_volume(q);
  e.direction_cross = cross(da, db);
  const auto d = dot(e.direction_cross, e.direction_cross);
  const auto u = dot(cross(r, db), e.direction_cross);
  const auto w = dot(cross(r, da), e.direction_cross);
  e.parameters = {u, d - u, w, d - w};
  e.endpoint_on_edge = {point_on_segment_polys(a0, b0, b1), point_on_segment_polys(a1, b0, b1),
                        point_on_segment_polys(b0, a0, a1), point_on_segment_polys(b1, a0, a1)};
  return e;
}

/// Calls f on every polynomial the contact rule may consult apart from the volume: the
/// candidate times of a query that is coplanar for all t are the roots of these.
template <class NT, class F>
void for_each_in_plane_poly(const VertexFacePolys<NT>& P, F&& f) {
  f(P.normal.x), f(P.normal.y), f(P.normal.z);
  for (const auto& b : P.barycentric) f(b);
  for (const auto& s : P.on_edge) f(s.cross.x), f(s.cross.y), f(s.cross.z), f(s.dot);
}

template <class NT, class F>
void for_each_in_plane_poly(const EdgeEdgePolys<NT>& P, F&& f) {
  f(P.direction_cross.x), f(P.direction_cross.y), f(P.direction_cross.z);
  for (const auto& u : P.parameters) f(u);
  for (const auto& s : P.endpoint_on_edge) f(s.cross.x), f(s.cross.y), f(s.cross.z), f(s.dot);
}

}  // namespace exactccd::contact
