// The contact rule: "are the primitives in contact at time t?" as a Boolean formula over the
// signs of the polynomials of contact_polynomials.hpp. Written once; every method evaluates
// it with its own sign oracle (exact signs at algebraic roots, certified interval signs, ...).
// The proof that the formula is the contract is in docs/design.md.
//
// A sign oracle is a callable `int sign(const Poly<NT, D>&)` returning -1, 0 or +1 for the
// polynomial's value at the time being examined, or kUnknownSign when it cannot certify the
// sign. The rule then evaluates in three-valued logic (as CGAL's Uncertain<bool>): a
// conjunction is false as soon as one operand is certainly false, a disjunction true as soon as
// one is certainly true, whatever the unknown operands; only otherwise is the result unknown.
// Exact oracles never answer kUnknownSign, and then the rule is plain Boolean logic.
#pragma once

#include <type_traits>
#include <utility>

#include "contact/contact_polynomials.hpp"
#include "numeric/interval.hpp"

namespace exactccd::contact {

using numeric::kUnknownSign;  ///< the oracle's answer when a sign is not certain

/// A three-valued truth value.
enum class Truth { no, yes, unknown };

inline Truth truth(bool b) { return b ? Truth::yes : Truth::no; }

/// "The sign s is zero" in three-valued logic.
inline Truth is_zero_sign(int s) { return s == kUnknownSign ? Truth::unknown : truth(s == 0); }

/// "The sign s is >= 0" in three-valued logic.
inline Truth is_nonnegative_sign(int s) { return s == kUnknownSign ? Truth::unknown : truth(s >= 0); }

/// Conjunction of lazily evaluated operands (callables returning Truth), left to right: stops
/// at the first certain `no`.
template <class... Fs>
Truth all_of(Fs&&... operands) {
  bool unknown = false;
  const auto stop = [&](auto&& f) {  // true: a certain `no` decides
    const Truth t = f();
    unknown = unknown || t == Truth::unknown;
    return t == Truth::no;
  };
  if ((stop(operands) || ...)) return Truth::no;
  return unknown ? Truth::unknown : Truth::yes;
}

/// Disjunction of lazily evaluated operands, left to right: stops at the first certain `yes`.
template <class... Fs>
Truth any_of(Fs&&... operands) {
  bool unknown = false;
  const auto stop = [&](auto&& f) {  // true: a certain `yes` decides
    const Truth t = f();
    unknown = unknown || t == Truth::unknown;
    return t == Truth::yes;
  };
  if ((stop(operands) || ...)) return Truth::yes;
  return unknown ? Truth::unknown : Truth::no;
}

/// The point lies on the closed segment (see PointOnSegmentPolys).
template <class PointOnSegment, class SignOracle>
Truth point_on_segment(const PointOnSegment& s, SignOracle&& sign) {
  return all_of([&] { return is_zero_sign(sign(s.cross.x)); },
                [&] { return is_zero_sign(sign(s.cross.y)); },
                [&] { return is_zero_sign(sign(s.cross.z)); },
                [&] { return is_nonnegative_sign(sign(s.dot)); });
}

/// The vector polynomial is nonzero at the time examined.
template <class Vector, class SignOracle>
Truth is_nonzero(const Vector& v, SignOracle&& sign) {
  const auto nonzero = [&](const auto& p) {
    const int s = sign(p);
    return s == kUnknownSign ? Truth::unknown : truth(s != 0);
  };
  return any_of([&] { return nonzero(v.x); }, [&] { return nonzero(v.y); },
                [&] { return nonzero(v.z); });
}

/// Chooses between the answers of a case split on `condition`; when the condition is unknown
/// both branches are evaluated and the answer is certain only if they agree.
template <class Then, class Else>
Truth branch(Truth condition, Then&& if_yes, Else&& if_no) {
  if (condition == Truth::yes) return if_yes();
  if (condition == Truth::no) return if_no();
  const Truth a = if_yes();
  return a == Truth::unknown || a != if_no() ? Truth::unknown : a;
}

/// p lies on one of the triangle's three closed edges.
template <class Polys, class SignOracle>
Truth vertex_on_an_edge(const Polys& P, SignOracle&& sign) {
  return any_of([&] { return point_on_segment(P.on_edge(0), sign); },
                [&] { return point_on_segment(P.on_edge(1), sign); },
                [&] { return point_on_segment(P.on_edge(2), sign); });
}

/// An endpoint of one edge lies on the other closed edge.
template <class Polys, class SignOracle>
Truth endpoint_on_other_edge(const Polys& P, SignOracle&& sign) {
  return any_of([&] { return point_on_segment(P.endpoint_on_edge(0), sign); },
                [&] { return point_on_segment(P.endpoint_on_edge(1), sign); },
                [&] { return point_on_segment(P.endpoint_on_edge(2), sign); },
                [&] { return point_on_segment(P.endpoint_on_edge(3), sign); });
}

/// The rule's answer `t`, refined where it is unknown by a sufficient condition for contact:
/// `contact_if_yes` implies contact whatever the branch, so its certain "yes" decides. Exact
/// oracles never leave `t` unknown, so they never pay for the refinement. It matters where
/// the branch hinges on a sign that is exactly zero (a point exactly on an edge makes a
/// barycentric numerator or a segment parameter vanish, which an interval cannot certify)
/// while the edge test is certain (its defining polynomial is the one whose root is examined).
template <class Sufficient>
Truth refined(Truth t, Sufficient&& contact_if_yes) {
  if (t != Truth::unknown) return t;
  return contact_if_yes() == Truth::yes ? Truth::yes : Truth::unknown;
}

/// Vertex-face contact at a time where the volume V vanishes (p is in the triangle's plane,
/// or the triangle is degenerate):
/// - proper triangle (n != 0): p is inside iff its three barycentric numerators
///   n . (e_i x (p - v_i)) = |n|^2 lambda_i are all >= 0;
/// - degenerate triangle (n == 0: a, b, c collinear or coincident): the hull is the union of
///   the three closed segments ab, bc, ca.
/// p on a closed edge is in the hull in either case (see refined()).
template <class Polys, class SignOracle>
Truth vertex_face_in_plane_contact(const Polys& P, SignOracle&& sign) {
  const Truth t = branch(
      is_nonzero(P.normal(), sign),
      [&] {
        return all_of([&] { return is_nonnegative_sign(sign(P.barycentric(0))); },
                      [&] { return is_nonnegative_sign(sign(P.barycentric(1))); },
                      [&] { return is_nonnegative_sign(sign(P.barycentric(2))); });
      },
      [&] { return vertex_on_an_edge(P, sign); });
  return refined(t, [&] { return vertex_on_an_edge(P, sign); });
}

/// Edge-edge contact at a time where the volume V vanishes (the edges are coplanar):
/// - not parallel (w = da x db != 0): the lines meet at one point with parameters
///   alpha = U / D, beta = W / D; contact iff both lie in [0, 1];
/// - parallel, collinear or zero-length (w == 0): the segments meet iff an endpoint of one lies
///   on the other (the intersection of two collinear segments is bounded by such endpoints).
/// An endpoint on the other segment is a common point in either case (see refined()).
template <class Polys, class SignOracle>
Truth edge_edge_in_plane_contact(const Polys& P, SignOracle&& sign) {
  const Truth t = branch(
      is_nonzero(P.direction_cross(), sign),
      [&] {
        return all_of([&] { return is_nonnegative_sign(sign(P.parameter(0))); },
                      [&] { return is_nonnegative_sign(sign(P.parameter(1))); },
                      [&] { return is_nonnegative_sign(sign(P.parameter(2))); },
                      [&] { return is_nonnegative_sign(sign(P.parameter(3))); });
      },
      [&] { return endpoint_on_other_edge(P, sign); });
  return refined(t, [&] { return endpoint_on_other_edge(P, sign); });
}

/// True for a vertex-face polynomial set (anything with normal(), barycentric(i) and
/// on_edge(i): VertexFacePolys or an adapter with the same accessors).
template <class Polys, class = void>
struct is_vertex_face_polys : std::false_type {};
template <class Polys>
struct is_vertex_face_polys<Polys, std::void_t<decltype(std::declval<const Polys&>().normal())>>
    : std::true_type {};

/// The in-plane part of the contact rule, chosen by the kind of the polynomial set.
template <class Polys, class SignOracle>
Truth in_plane_contact(const Polys& P, SignOracle&& sign) {
  if constexpr (is_vertex_face_polys<Polys>::value)
    return vertex_face_in_plane_contact(P, sign);
  else
    return edge_edge_in_plane_contact(P, sign);
}

/// The whole contact rule at one time: the volume vanishes (the four points are coplanar)
/// and the in-plane rule holds.
template <class Polys, class SignOracle>
Truth in_contact(const Polys& P, SignOracle&& sign) {
  return all_of([&] { return is_zero_sign(sign(P.volume())); },
                [&] { return in_plane_contact(P, sign); });
}

}  // namespace exactccd::contact
