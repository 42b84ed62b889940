// The contact rule: "are the primitives in contact at time t?" as a Boolean formula over the
// signs of the polynomials of contact_polynomials.hpp. Written once; every method evaluates
// it with its own sign oracle (exact signs at algebraic roots, certified interval signs that
// give up when uncertain, ...). The proof that the formula is the contract is in
// docs/design.md.
//
// A sign oracle is a callable `int sign(const Poly<NT, D>&)` returning -1, 0 or +1 for the
// polynomial's value at the time being examined. An oracle that cannot certify a sign may
// throw; the rule has no state, so the caller can retry the query with a stronger oracle.
#pragma once

#include "contact/contact_polynomials.hpp"

namespace exactccd::contact {

/// True iff the point lies on the closed segment (see PointOnSegmentPolys).
template <class NT, class SignOracle>
bool point_on_segment(const PointOnSegmentPolys<NT>& s, SignOracle&& sign) {
  return sign(s.cross.x) == 0 && sign(s.cross.y) == 0 && sign(s.cross.z) == 0 && sign(s.dot) >= 0;
}

template <class NT, class SignOracle>
bool is_nonzero(const PolyVec3<NT, 2>& v, SignOracle&& sign) {
  return sign(v.x) != 0 || sign(v.y) != 0 || sign(v.z) != 0;
}

/// Vertex-face contact at a time where the volume V vanishes (p is in the triangle's plane,
/// or the triangle is degenerate):
/// - proper triangle (n != 0): p is inside iff its three barycentric numerators
///   n . (e_i x (p - v_i)) = |n|^2 lambda_i are all >= 0;
/// - degenerate triangle (n == 0: a, b, c collinear or coincident): the hull is the union of
///   the three closed segments ab, bc, ca.
template <class NT, class SignOracle>
bool vertex_face_in_plane_contact(const VertexFacePolys<NT>& P, SignOracle&& sign) {
  if (is_nonzero(P.normal(), sign))
    return sign(P.barycentric(0)) >= 0 && sign(P.barycentric(1)) >= 0 &&
           sign(P.barycentric(2)) >= 0;
  return point_on_segment(P.on_edge(0), sign) || point_on_segment(P.on_edge(1), sign) ||
         point_on_segment(P.on_edge(2), sign);
}

/// Edge-edge contact at a time where the volume V vanishes (the edges are coplanar):
/// - not parallel (w = da x db != 0): the lines meet at one point with parameters
///   alpha = U / D, beta = W / D; contact iff both lie in [0, 1];
/// - parallel, collinear or zero-length (w == 0): the segments meet iff an endpoint of one lies
///   on the other (the intersection of two collinear segments is bounded by such endpoints).
template <class NT, class SignOracle>
bool edge_edge_in_plane_contact(const EdgeEdgePolys<NT>& P, SignOracle&& sign) {
  if (is_nonzero(P.direction_cross(), sign))
    return sign(P.parameter(0)) >= 0 && sign(P.parameter(1)) >= 0 &&
           sign(P.parameter(2)) >= 0 && sign(P.parameter(3)) >= 0;
  return point_on_segment(P.endpoint_on_edge(0), sign) ||
         point_on_segment(P.endpoint_on_edge(1), sign) ||
         point_on_segment(P.endpoint_on_edge(2), sign) ||
         point_on_segment(P.endpoint_on_edge(3), sign);
}

/// The in-plane part of the contact rule, chosen by overload.
template <class NT, class SignOracle>
bool in_plane_contact(const VertexFacePolys<NT>& P, SignOracle&& sign) {
  return vertex_face_in_plane_contact(P, sign);
}
template <class NT, class SignOracle>
bool in_plane_contact(const EdgeEdgePolys<NT>& P, SignOracle&& sign) {
  return edge_edge_in_plane_contact(P, sign);
}

/// The whole contact rule at one time: the volume vanishes (the four points are coplanar)
/// and the in-plane rule holds.
template <class Polys, class SignOracle>
bool in_contact(const Polys& P, SignOracle&& sign) {
  return sign(P.volume()) == 0 && in_plane_contact(P, sign);
}

}  // namespace exactccd::contact
