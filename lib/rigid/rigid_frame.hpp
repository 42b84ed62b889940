// The rigid motion model in body B's frame (docs/design.md, 9.1-9.2).
//
// A rigid query's positions are rational in t. In B's frame (a rotation and a translation of
// world space, which change no distance) B's points are constant and an A point p is
//   Y(t) = R(qB)^T (cA - cB) + R(qB)^T R(qA) p = N(t) / D(t),
//   D = |qA|^2 |qB|^2 (degree 4, > 0 on [0, 1] for valid input),
//   N = M(conj(qB)) (cA - cB) |qA|^2 + M(conj(qB) qA) p (degree 5; quaternion.hpp).
// Every polynomial of the contact rule and every feature-pair term is homogeneous in the
// points' differences (and d, counted as a length): multiplying every position and d by D(t)
// multiplies it by D(t)^k, a positive factor, so its sign at every t is unchanged. So the
// rule's own templates (contact_polynomials.hpp, separation_terms.hpp) run unchanged on the
// "positions times D": A points N(t), B points D(t) b, and d D(t), all polynomials; their
// results are the true values times D^k, which the exact path then divides by the factors
// |qA|^2 and |qB|^2 of D wherever they divide (exactly), down to the degrees of 9.2.
#pragma once

#include <array>
#include <type_traits>
#include <utility>

#include "contact/contact_polynomials.hpp"
#include "contact/polynomial.hpp"
#include "exactccd/rigid.hpp"
#include "kinds/primitive_kinds.hpp"
#include "rigid/quaternion.hpp"

namespace exactccd::rigid {

/// The four poses of a query: A at t0, A at t1, B at t0, B at t1.
template <class Query>
auto poses(const Query& q) {
  return std::array<std::decay_t<decltype(q.a_t0)>, 4>{q.a_t0, q.a_t1, q.b_t0, q.b_t1};
}

/// The motion x0 + t (x1 - x0) of each coordinate.
template <class NT>
contact::PolyVec3<NT, 1> linear_path(const Vec3T<NT>& x0, const Vec3T<NT>& x1) {
  return {contact::linear_motion(x0.x, x1.x), contact::linear_motion(x0.y, x1.y),
          contact::linear_motion(x0.z, x1.z)};
}

/// The quaternion path q0 + t (q1 - q0).
template <class NT>
QuaternionT<contact::Poly<NT, 1>> linear_path(const QuaternionT<NT>& q0, const QuaternionT<NT>& q1) {
  return {contact::linear_motion(q0.w, q1.w), contact::linear_motion(q0.x, q1.x),
          contact::linear_motion(q0.y, q1.y), contact::linear_motion(q0.z, q1.z)};
}

/// p as a polynomial of degree D (higher coefficients zero).
template <int D, class NT, int E>
contact::Poly<NT, D> widen(const contact::Poly<NT, E>& p) {
  static_assert(E <= D);
  auto r = contact::Poly<NT, D>::zero();
  for (int k = 0; k <= E; ++k) r.c[k] = p.c[k];
  return r;
}

/// A query's positions in B's frame times D(t) (file comment), as polynomials in t, with the
/// positive factors |qA(t)|^2, |qB(t)|^2 of D.
template <class NT>
struct ScaledFrame {
  std::array<contact::PolyVec3<NT, 5>, 4> position;  ///< the kind's points: D Y (A) or D b (B)
  contact::Poly<NT, 2> norm_a;                        ///< |qA(t)|^2
  contact::Poly<NT, 2> norm_b;                        ///< |qB(t)|^2
  contact::Poly<NT, 4> D;                             ///< |qA(t)|^2 |qB(t)|^2
};

/// The parts of the scaled frame shared by every point (file comment): the norms, D, the
/// relative rotation conj(qB) qA and the rotated translation M(conj qB)(cA - cB).
template <class Query>
class ScaledFrameParts {
 public:
  using NT = std::decay_t<decltype(std::declval<const Query&>().a_t0.c.x)>;
  using P0 = contact::Poly<NT, 0>;

  explicit ScaledFrameParts(const Query& q) {
    const auto qa = linear_path(q.a_t0.q, q.a_t1.q), qb = linear_path(q.b_t0.q, q.b_t1.q);
    norm_a = squared_norm(qa);
    norm_b = squared_norm(qb);
    D = norm_a * norm_b;
    const auto negate = [](const contact::Poly<NT, 1>& p) { return P0::zero() - p; };
    const auto qb_conj = conjugate(qb, negate);
    relative = product(qb_conj, qa);  // degree 2: M(relative) = D R(qB)^T R(qA)
    using contact::operator-;
    const auto dc = linear_path(q.a_t0.c, q.a_t1.c) - linear_path(q.b_t0.c, q.b_t1.c);
    translation = rotate_scaled(qb_conj, dc);  // M(qB)^T (cA - cB): degree 3
  }

  /// D(t) times the position of body point p (of body A when on_a, else of B) in B's frame.
  contact::PolyVec3<NT, 5> position(const Vec3T<NT>& point, bool on_a) const {
    const Vec3T<P0> p{P0{{point.x}}, P0{{point.y}}, P0{{point.z}}};
    if (on_a) {
      const auto r = rotate_scaled(relative, p);  // degree 4
      return {translation.x * norm_a + widen<5>(r.x), translation.y * norm_a + widen<5>(r.y),
              translation.z * norm_a + widen<5>(r.z)};
    }
    return {widen<5>(p.x * D), widen<5>(p.y * D), widen<5>(p.z * D)};
  }

  contact::Poly<NT, 2> norm_a;  ///< |qA(t)|^2
  contact::Poly<NT, 2> norm_b;  ///< |qB(t)|^2
  contact::Poly<NT, 4> D;       ///< |qA(t)|^2 |qB(t)|^2
  QuaternionT<contact::Poly<NT, 2>> relative;  ///< conj(qB(t)) qA(t)
  contact::PolyVec3<NT, 3> translation;         ///< M(conj qB(t)) (cA(t) - cB(t))
};

/// The scaled frame of a query with coordinates of an exact ring NT (mpz_class, mpq_class) or
/// intervals.
template <class Query>
auto scaled_frame(const Query& q) {
  using Kind = kinds::kind_of<Query>;
  const ScaledFrameParts<Query> parts(q);
  ScaledFrame<typename ScaledFrameParts<Query>::NT> f;
  f.norm_a = parts.norm_a;
  f.norm_b = parts.norm_b;
  f.D = parts.D;
  const auto points = body_points(q);
  for (int i = 0; i < 4; ++i) f.position[i] = parts.position(points[i], i < Kind::first_points);
  return f;
}

/// The relative motions of a scaled frame's points (the Motion of contact_polynomials.hpp):
/// rel(i, j) = D (Y_j - Y_i), polynomials of degree <= 5.
template <class NT>
class ScaledFrameMotion {
 public:
  explicit ScaledFrameMotion(const ScaledFrame<NT>& frame) : position_(frame.position) {}
  /// D(t) times the vector from point `from` to point `to` (the kind's point indices).
  contact::PolyVec3<NT, 5> rel(int from, int to) const {
    using contact::operator-;
    return position_[to] - position_[from];
  }

 private:
  std::array<contact::PolyVec3<NT, 5>, 4> position_;
};

/// The contact rule's terms of a rigid query, on the scaled frame (vertex-face or edge-edge by
/// the query's kind).
template <class Query, class NT>
auto contact_terms(const ScaledFrame<NT>& frame) {
  if constexpr (std::is_same_v<kinds::kind_of<Query>, kinds::VertexFace>)
    return contact::VertexFaceTerms<ScaledFrameMotion<NT>>(ScaledFrameMotion<NT>(frame));
  else
    return contact::EdgeEdgeTerms<ScaledFrameMotion<NT>>(ScaledFrameMotion<NT>(frame));
}

}  // namespace exactccd::rigid
