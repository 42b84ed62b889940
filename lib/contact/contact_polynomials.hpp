// The named polynomials in t whose signs decide contact (docs/design.md, "The contact rule").
//
// Written once per kind (VertexFaceTerms, EdgeEdgeTerms), templated on a Motion that gives the
// relative motion of two points of the query:
// - PolynomialMotion<NT>: linear polynomials in t with coefficients NT (mpq_class or mpz_class on
//   the exact paths, CGAL::Interval_nt in the interval filter, double in the naive baseline);
//   every term is then a polynomial (VertexFacePolys<NT>, EdgeEdgePolys<NT>);
// - a motion evaluated over one time interval T (the interval filter's MotionOver,
//   filter/interval/values.hpp): every term is then an interval enclosing the polynomial's
//   values over T, from the same formulas, without building the polynomials.
// Each term is built on first use and cached: the rule usually needs only a few of them
// (a proper triangle never asks for its edges' segment tests), and on the exact paths every
// multiplication costs a GMP call. A term set belongs to one query and one thread.
#pragma once

#include <array>
#include <optional>
#include <type_traits>
#include <utility>

#include "contact/polynomial.hpp"
#include "contact/vec3_ops.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/types.hpp"

namespace exactccd::contact {

template <class NT, int D>
using PolyVec3 = Vec3T<Poly<NT, D>>;

/// Terms deciding "q(t) lies on the closed segment [u(t), v(t)]":
/// cross = (q - u) x (v - u) vanishes (q on the line, or u == v), and
/// dot = (q - u) . (v - q) >= 0 (q between u and v; with u == v it forces q == u).
template <class Vector, class Scalar>
struct PointOnSegment {
  Vector cross;
  Scalar dot;
};

/// The point-on-segment polynomials.
template <class NT>
using PointOnSegmentPolys = PointOnSegment<PolyVec3<NT, 2>, Poly<NT, 2>>;

/// The motion of the vector from point `from` to point `to` (rows of a query: the point at t0,
/// and at t1 four rows later): (to - from)(t) = d0 + t (d1 - d0) with d0, d1 the differences
/// at t0 and t1. Differencing the positions first (rather than the two points' motions) keeps
/// the terms small where points are close to each other and far from the origin: with interval
/// or floating-point coefficients, each difference of nearby doubles is exact (Sterbenz) and the
/// rounding is relative to the edge length, not to the coordinates; exactly equal coordinates
/// give exactly zero coefficients. Exact number types get the same polynomial either way.
template <class NT>
PolyVec3<NT, 1> relative_motion(const std::array<Vec3T<NT>, 8>& rows, int from, int to) {
  const Vec3T<NT>&u0 = rows[from], &u1 = rows[from + 4], &v0 = rows[to], &v1 = rows[to + 4];
  return {linear_motion(NT(v0.x - u0.x), NT(v1.x - u1.x)), linear_motion(NT(v0.y - u0.y), NT(v1.y - u1.y)),
          linear_motion(NT(v0.z - u0.z), NT(v1.z - u1.z))};
}

/// "q on [u, v]" from the relative motions u -> q, u -> v and q -> v.
template <class Vector>
auto point_on_segment_terms(const Vector& uq, const Vector& uv, const Vector& qv) {
  return PointOnSegment<decltype(cross(uq, uv)), decltype(dot(uq, qv))>{cross(uq, uv), dot(uq, qv)};
}

/// The relative motions of a query's points as linear polynomials in t.
template <class NT>
class PolynomialMotion {
 public:
  explicit PolynomialMotion(const std::array<Vec3T<NT>, 8>& rows) : rows_(rows) {}
  /// The motion of the vector from row `from` to row `to` (relative_motion).
  PolyVec3<NT, 1> rel(int from, int to) const { return relative_motion(rows_, from, to); }
  /// The query's rows (t0 rows, then t1 rows).
  const std::array<Vec3T<NT>, 8>& rows() const { return rows_; }

 private:
  std::array<Vec3T<NT>, 8> rows_;
};

/// The types of the terms built from a Motion's relative motions (degree 1 for polynomials):
/// vectors of degree 2 (cross products), scalars of degree 2, 3 and 4.
template <class Motion>
struct TermTypes {
  using Vector1 = std::decay_t<decltype(std::declval<const Motion&>().rel(0, 1))>;
  using Vector2 = decltype(cross(std::declval<const Vector1&>(), std::declval<const Vector1&>()));
  using Scalar2 = decltype(dot(std::declval<const Vector1&>(), std::declval<const Vector1&>()));
  using Scalar3 = decltype(dot(std::declval<const Vector1&>(), std::declval<const Vector2&>()));
  using Scalar4 = decltype(dot(std::declval<const Vector2&>(), std::declval<const Vector2&>()));
  using OnSegment = PointOnSegment<Vector2, Scalar2>;
};

/// What the term classes of both kinds share: the motion their terms are built from.
template <class Motion>
class MotionTerms {
 public:
  explicit MotionTerms(Motion motion) : motion_(std::move(motion)) {}
  /// With the motion constructed in place from `args`.
  template <class... Args>
  explicit MotionTerms(std::in_place_t, Args&&... args) : motion_(std::forward<Args>(args)...) {}
  /// The motion the terms are built from.
  const Motion& motion() const { return motion_; }

 protected:
  /// The relative motion from row `from` to row `to` (rows at t0; t1 four rows later).
  decltype(auto) rel(int from, int to) const { return motion_.rel(from, to); }

 private:
  Motion motion_;
};

/// Returns the cached value, computing it with make() on first use.
template <class T, class Make>
const T& cached(std::optional<T>& slot, Make&& make) {
  if (!slot) slot.emplace(make());
  return *slot;
}

/// Vertex-face terms of p against triangle (a, b, c), built from a Motion (file comment).
template <class Motion>
class VertexFaceTerms : public MotionTerms<Motion> {
  using Types = TermTypes<Motion>;
  using MotionTerms<Motion>::rel;

 public:
  using MotionTerms<Motion>::MotionTerms;

  /// V = (b - a) . ((c - a) x (p - a)): zero iff the four points are coplanar.
  const typename Types::Scalar3& volume() const {
    return cached(volume_, [&] { return dot(rel(kA, kB), cross(rel(kA, kC), rel(kA, kP))); });
  }
  /// n = (b - a) x (c - a): zero iff the triangle is degenerate.
  const typename Types::Vector2& normal() const {
    return cached(normal_, [&] { return cross(rel(kA, kB), rel(kA, kC)); });
  }
  /// n . (e_i x (p - v_i)) for the edges (a, b), (b, c), (c, a): |n|^2 times the barycentric
  /// coordinate of p opposite the edge, when p is in the plane.
  const typename Types::Scalar4& barycentric(int i) const {
    return cached(barycentric_[i], [&] {
      const auto [u, v] = edge(i);
      return dot(normal(), cross(rel(u, v), rel(u, kP)));
    });
  }
  /// "p on the closed edge i" (see PointOnSegment).
  const typename Types::OnSegment& on_edge(int i) const {
    return cached(on_edge_[i], [&] {
      const auto [u, v] = edge(i);
      return point_on_segment_terms(rel(u, kP), rel(u, v), rel(kP, v));
    });
  }

 private:
  static constexpr int kP = 0, kA = 1, kB = 2, kC = 3;  // rows at t0 (t1: four rows later)
  static std::pair<int, int> edge(int i) {
    if (i == 0) return {kA, kB};
    if (i == 1) return {kB, kC};
    return {kC, kA};
  }
  mutable std::optional<typename Types::Scalar3> volume_;
  mutable std::optional<typename Types::Vector2> normal_;
  mutable std::array<std::optional<typename Types::Scalar4>, 3> barycentric_;
  mutable std::array<std::optional<typename Types::OnSegment>, 3> on_edge_;
};

/// Vertex-face polynomials of p against triangle (a, b, c).
template <class NT>
class VertexFacePolys : public VertexFaceTerms<PolynomialMotion<NT>> {
 public:
  explicit VertexFacePolys(const VertexFaceQueryT<NT>& q)
      : VertexFaceTerms<PolynomialMotion<NT>>(PolynomialMotion<NT>(rows(q))) {}
};

/// Edge-edge terms of segment (a0, a1) against segment (b0, b1), built from a Motion.
/// With da = a1 - a0, db = b1 - b0, r = b0 - a0, w = da x db, D = w . w, the coplanar lines
/// meet at a0 + (U / D) da = b0 + (W / D) db where U = (r x db) . w and W = (r x da) . w.
template <class Motion>
class EdgeEdgeTerms : public MotionTerms<Motion> {
  using Types = TermTypes<Motion>;
  using MotionTerms<Motion>::rel;

 public:
  using MotionTerms<Motion>::MotionTerms;

  /// V = (a1 - a0) . ((b0 - a0) x (b1 - a0)): zero iff the four points are coplanar.
  const typename Types::Scalar3& volume() const {
    return cached(volume_, [&] { return dot(rel(kA0, kA1), cross(rel(kA0, kB0), rel(kA0, kB1))); });
  }
  /// w = da x db: zero iff the edges are parallel or one has zero length.
  const typename Types::Vector2& direction_cross() const {
    return cached(direction_cross_, [&] { return cross(rel(kA0, kA1), rel(kB0, kB1)); });
  }
  /// U, D - U, W, D - W for i = 0..3: all >= 0 iff alpha = U / D and beta = W / D are in [0, 1].
  const typename Types::Scalar4& parameter(int i) const {
    return cached(parameter_[i], [&] {
      // U (i < 2) or W (i >= 2), each built once and shared by its pair.
      const auto& numerator = cached(numerator_[i / 2], [&] {
        return dot(cross(rel(kA0, kB0), i < 2 ? rel(kB0, kB1) : rel(kA0, kA1)), direction_cross());
      });
      if (i % 2 == 0) return numerator;
      const auto& d = cached(squared_norm_, [&] { return dot(direction_cross(), direction_cross()); });
      return typename Types::Scalar4(d - numerator);
    });
  }
  /// a0 on edge b, a1 on edge b, b0 on edge a, b1 on edge a, for i = 0..3.
  const typename Types::OnSegment& endpoint_on_edge(int i) const {
    return cached(endpoint_on_edge_[i], [&] {
      // The point q = row i against the other edge [u, v].
      const int q = i, u = i < 2 ? kB0 : kA0, v = i < 2 ? kB1 : kA1;
      return point_on_segment_terms(rel(u, q), rel(u, v), rel(q, v));
    });
  }

 private:
  static constexpr int kA0 = 0, kA1 = 1, kB0 = 2, kB1 = 3;  // rows at t0 (t1: four rows later)
  mutable std::optional<typename Types::Scalar3> volume_;
  mutable std::optional<typename Types::Vector2> direction_cross_;
  mutable std::array<std::optional<typename Types::Scalar4>, 2> numerator_;  // U, W
  mutable std::optional<typename Types::Scalar4> squared_norm_;               // D = w . w
  mutable std::array<std::optional<typename Types::Scalar4>, 4> parameter_;
  mutable std::array<std::optional<typename Types::OnSegment>, 4> endpoint_on_edge_;
};

/// Edge-edge polynomials of segment (a0, a1) against segment (b0, b1).
template <class NT>
class EdgeEdgePolys : public EdgeEdgeTerms<PolynomialMotion<NT>> {
 public:
  explicit EdgeEdgePolys(const EdgeEdgeQueryT<NT>& q)
      : EdgeEdgeTerms<PolynomialMotion<NT>>(PolynomialMotion<NT>(rows(q))) {}
};

/// The polynomial set of a query, chosen by overload.
template <class NT>
VertexFacePolys<NT> polynomials(const VertexFaceQueryT<NT>& q) {
  return VertexFacePolys<NT>(q);
}
template <class NT>
EdgeEdgePolys<NT> polynomials(const EdgeEdgeQueryT<NT>& q) {
  return EdgeEdgePolys<NT>(q);
}

// The in-plane rule (contact_rule.hpp) branches on one vector polynomial (the normal n, or
// w = da x db): where it is nonzero it consults the "proper" polynomials (barycentric
// numerators, segment parameters), where it vanishes the "degenerate" ones (point on segment).

/// The vector polynomial the in-plane rule branches on (for terms built from any Motion: the
/// linear polynomials of VertexFacePolys / EdgeEdgePolys, or another motion model's).
template <class Motion>
const auto& branch_vector(const VertexFaceTerms<Motion>& P) {
  return P.normal();
}
template <class Motion>
const auto& branch_vector(const EdgeEdgeTerms<Motion>& P) {
  return P.direction_cross();
}

/// Calls f on the polynomials of the branch where the branch vector is nonzero.
template <class Motion, class F>
void for_each_proper_poly(const VertexFaceTerms<Motion>& P, F&& f) {
  for (int i = 0; i < 3; ++i) f(P.barycentric(i));
}
template <class Motion, class F>
void for_each_proper_poly(const EdgeEdgeTerms<Motion>& P, F&& f) {
  for (int i = 0; i < 4; ++i) f(P.parameter(i));
}

/// Calls f on the polynomials of the branch where the branch vector vanishes.
template <class Motion, class F>
void for_each_degenerate_poly(const VertexFaceTerms<Motion>& P, F&& f) {
  for (int i = 0; i < 3; ++i) {
    const auto& s = P.on_edge(i);
    f(s.cross.x), f(s.cross.y), f(s.cross.z), f(s.dot);
  }
}
template <class Motion, class F>
void for_each_degenerate_poly(const EdgeEdgeTerms<Motion>& P, F&& f) {
  for (int i = 0; i < 4; ++i) {
    const auto& s = P.endpoint_on_edge(i);
    f(s.cross.x), f(s.cross.y), f(s.cross.z), f(s.dot);
  }
}

/// Calls f on every polynomial the contact rule may consult apart from the volume: the
/// candidate times of a query that is coplanar for all t are the roots of these. Their index in
/// this order is visit_in_plane_poly's.
template <class Polys, class F>
void for_each_in_plane_poly(const Polys& P, F&& f) {
  const auto& v = branch_vector(P);
  f(v.x), f(v.y), f(v.z);
  for_each_proper_poly(P, f);
  for_each_degenerate_poly(P, f);
}

/// How many proper polynomials the kind has (for_each_proper_poly): 3 barycentric numerators,
/// or 4 segment parameters.
template <class Motion>
constexpr int proper_poly_count(const VertexFaceTerms<Motion>&) {
  return 3;
}
template <class Motion>
constexpr int proper_poly_count(const EdgeEdgeTerms<Motion>&) {
  return 4;
}

/// The index in for_each_in_plane_poly's order of the first proper polynomial (after the
/// branch vector's three components) and of the first degenerate one.
inline constexpr int kFirstProperPoly = 3;
template <class Polys>
constexpr int first_degenerate_poly(const Polys& P) {
  return kFirstProperPoly + proper_poly_count(P);
}

/// The i-th proper polynomial (for_each_proper_poly's order).
template <class Motion>
const auto& proper_poly(const VertexFaceTerms<Motion>& P, int i) {
  return P.barycentric(i);
}
template <class Motion>
const auto& proper_poly(const EdgeEdgeTerms<Motion>& P, int i) {
  return P.parameter(i);
}

/// How many point-on-segment tests the degenerate branch has (for_each_degenerate_poly: four
/// polynomials each): p on the triangle's 3 edges, or the 4 endpoints on the other edge.
template <class Motion>
constexpr int degenerate_segment_count(const VertexFaceTerms<Motion>&) {
  return 3;
}
template <class Motion>
constexpr int degenerate_segment_count(const EdgeEdgeTerms<Motion>&) {
  return 4;
}

/// The i-th point-on-segment test of the degenerate branch (for_each_degenerate_poly's order).
template <class Motion>
const auto& degenerate_segment(const VertexFaceTerms<Motion>& P, int i) {
  return P.on_edge(i);
}
template <class Motion>
const auto& degenerate_segment(const EdgeEdgeTerms<Motion>& P, int i) {
  return P.endpoint_on_edge(i);
}

/// Calls f on the in-plane polynomial of index `index` in for_each_in_plane_poly's order,
/// building only that one (and what it is made of); nothing for an index out of range.
template <class Polys, class F>
void visit_in_plane_poly(const Polys& P, int index, F&& f) {
  const int degenerate = first_degenerate_poly(P);
  if (index < 0) return;
  if (index < kFirstProperPoly) {
    const auto& v = branch_vector(P);
    f(index == 0 ? v.x : index == 1 ? v.y : v.z);
  } else if (index < degenerate) {
    f(proper_poly(P, index - kFirstProperPoly));
  } else if (const int k = index - degenerate; k < 4 * degenerate_segment_count(P)) {
    const auto& s = degenerate_segment(P, k / 4);  // four polynomials per segment test
    if (k % 4 == 3)
      f(s.dot);
    else
      f(k % 4 == 0 ? s.cross.x : k % 4 == 1 ? s.cross.y : s.cross.z);
  }
}

}  // namespace exactccd::contact
