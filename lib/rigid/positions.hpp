// The positions of a rigid query's points in body B's frame times D(t) = |qA(t)|^2 |qB(t)|^2
// (rigid_frame.hpp), evaluated at one time in any exact or certified arithmetic (intervals,
// double-double with an error bound, GMP rationals): A's points N(t) = M(conj qB)(cA - cB) |qA|^2
// + M(conj(qB) qA) p, B's points D(t) b. Every polynomial of the contact rule and every
// feature-pair term, evaluated on these positions (and d D(t) in place of d), has the sign of
// the true value at t (homogeneity, docs/design.md 9.1). Used for certified signs at a double
// time (the TOI narrowing) and, in intervals, for values over a time cell.
#pragma once

#include <array>

#include "contact/contact_polynomials.hpp"
#include "exactccd/rigid.hpp"
#include "rigid/quaternion.hpp"
#include "rigid/rigid_frame.hpp"

namespace exactccd::rigid {

/// Scaled positions of a query's points at one time, with D at that time.
template <class R>
struct PositionsAt {
  std::array<Vec3T<R>, 4> point;  ///< D(t) times the kind's points in B's frame
  R D;                            ///< D(t) = |qA(t)|^2 |qB(t)|^2
};

/// The positions at a time given by the arithmetic `A`, which provides
///   R A::lerp(double x0, double x1)        x0 + t (x1 - x0) at the time,
///   R A::difference(double u0, double v0, double u1, double v1)   (v0 - u0) + t ((v1 - u1) - (v0 - u0)),
///   R A::constant(double x),  R A::negate(const R&).
template <class Query, class A>
auto positions_at(const Query& q, const A& arithmetic) {
  using R = decltype(arithmetic.constant(0.0));
  using Kind = kinds::kind_of<Query>;
  const auto lerp = [&](const Quaternion& a, const Quaternion& b) {
    return QuaternionT<R>{arithmetic.lerp(a.w, b.w), arithmetic.lerp(a.x, b.x), arithmetic.lerp(a.y, b.y),
                          arithmetic.lerp(a.z, b.z)};
  };
  const QuaternionT<R> qa = lerp(q.a_t0.q, q.a_t1.q), qb = lerp(q.b_t0.q, q.b_t1.q);
  const R na = squared_norm(qa), nb = squared_norm(qb);
  PositionsAt<R> out;
  out.D = na * nb;
  const QuaternionT<R> qb_conj = conjugate(qb, [&](const R& x) { return arithmetic.negate(x); });
  const QuaternionT<R> relative = product(qb_conj, qa);
  const Vec3T<R> dc{arithmetic.difference(q.b_t0.c.x, q.a_t0.c.x, q.b_t1.c.x, q.a_t1.c.x),
                    arithmetic.difference(q.b_t0.c.y, q.a_t0.c.y, q.b_t1.c.y, q.a_t1.c.y),
                    arithmetic.difference(q.b_t0.c.z, q.a_t0.c.z, q.b_t1.c.z, q.a_t1.c.z)};
  const Vec3T<R> translation = rotate_scaled(qb_conj, dc);
  const auto points = body_points(q);
  for (int i = 0; i < 4; ++i) {
    const Vec3T<R> p{arithmetic.constant(points[i].x), arithmetic.constant(points[i].y), arithmetic.constant(points[i].z)};
    if (i < Kind::first_points) {
      const Vec3T<R> r = rotate_scaled(relative, p);
      out.point[i] = {translation.x * na + r.x, translation.y * na + r.y, translation.z * na + r.z};
    } else {
      out.point[i] = {p.x * out.D, p.y * out.D, p.z * out.D};
    }
  }
  return out;
}

/// The relative motions of positions at one time (or over a cell): the Motion of the contact
/// rule's term classes (contact_polynomials.hpp).
template <class R>
class ValueMotion {
 public:
  explicit ValueMotion(const std::array<Vec3T<R>, 4>& point) : point_(point) {}
  /// The vector from point `from` to point `to`.
  Vec3T<R> rel(int from, int to) const {
    const Vec3T<R>&u = point_[from], &v = point_[to];
    return {v.x - u.x, v.y - u.y, v.z - u.z};
  }

 private:
  std::array<Vec3T<R>, 4> point_;
};

/// The contact rule's terms on values (vertex-face or edge-edge by the query's kind).
template <class Query, class R>
auto value_terms(const std::array<Vec3T<R>, 4>& point) {
  if constexpr (std::is_same_v<kinds::kind_of<Query>, kinds::VertexFace>)
    return contact::VertexFaceTerms<ValueMotion<R>>(ValueMotion<R>(point));
  else
    return contact::EdgeEdgeTerms<ValueMotion<R>>(ValueMotion<R>(point));
}

}  // namespace exactccd::rigid
