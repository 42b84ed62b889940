// exactccd: value types of the public API.
//
// A query is eight points: the positions of four vertices at t = 0 and at t = 1, in the
// row order of the public CCD benchmark (Wang et al. 2021). Vertices move linearly,
// x(t) = x_t0 + t (x_t1 - x_t0), t in [0, 1].
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

namespace exactccd {

/// A point or vector with three coordinates of number type T (double; mpq_class in
/// exactccd/rational.hpp).
template <class T>
struct Vec3T {
  T x;  ///< first coordinate
  T y;  ///< second coordinate
  T z;  ///< third coordinate
};

using Vec3 = Vec3T<double>;             ///< double coordinates

/// Vertex-face query: point p against triangle (a, b, c), each at t = 0 and t = 1.
/// Member order is the benchmark row order: p_t0, a_t0, b_t0, c_t0, p_t1, a_t1, b_t1, c_t1.
template <class T>
struct VertexFaceQueryT {
  Vec3T<T> p_t0;  ///< the vertex at t = 0
  Vec3T<T> a_t0;  ///< the triangle's first vertex at t = 0
  Vec3T<T> b_t0;  ///< the triangle's second vertex at t = 0
  Vec3T<T> c_t0;  ///< the triangle's third vertex at t = 0
  Vec3T<T> p_t1;  ///< the vertex at t = 1
  Vec3T<T> a_t1;  ///< the triangle's first vertex at t = 1
  Vec3T<T> b_t1;  ///< the triangle's second vertex at t = 1
  Vec3T<T> c_t1;  ///< the triangle's third vertex at t = 1
};

/// Edge-edge query: segment (a0, a1) against segment (b0, b1), each at t = 0 and t = 1.
/// Member order is the benchmark row order: a0_t0, a1_t0, b0_t0, b1_t0, a0_t1, a1_t1, b0_t1,
/// b1_t1.
template <class T>
struct EdgeEdgeQueryT {
  Vec3T<T> a0_t0;  ///< first endpoint of edge a at t = 0
  Vec3T<T> a1_t0;  ///< second endpoint of edge a at t = 0
  Vec3T<T> b0_t0;  ///< first endpoint of edge b at t = 0
  Vec3T<T> b1_t0;  ///< second endpoint of edge b at t = 0
  Vec3T<T> a0_t1;  ///< first endpoint of edge a at t = 1
  Vec3T<T> a1_t1;  ///< second endpoint of edge a at t = 1
  Vec3T<T> b0_t1;  ///< first endpoint of edge b at t = 1
  Vec3T<T> b1_t1;  ///< second endpoint of edge b at t = 1
};

using VertexFaceQuery = VertexFaceQueryT<double>;
using EdgeEdgeQuery = EdgeEdgeQueryT<double>;

/// The eight points of a query in benchmark row order (the four vertices at t0, then at t1).
template <class T>
std::array<Vec3T<T>, 8> rows(const VertexFaceQueryT<T>& q) {
  return {q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1};
}
template <class T>
std::array<Vec3T<T>, 8> rows(const EdgeEdgeQueryT<T>& q) {
  return {q.a0_t0, q.a1_t0, q.b0_t0, q.b1_t0, q.a0_t1, q.a1_t1, q.b0_t1, q.b1_t1};
}

/// A point or vector of the plane, for the 2D kinds.
template <class T>
struct Vec2T {
  T x;  ///< first coordinate
  T y;  ///< second coordinate
};

using Vec2 = Vec2T<double>;  ///< double coordinates in the plane

/// Point-edge query: point p against segment (a, b), each at t = 0 and t = 1.
/// Member order is the file row order: p_t0, a_t0, b_t0, p_t1, a_t1, b_t1.
template <class T>
struct PointEdgeQueryT {
  Vec3T<T> p_t0;  ///< the point at t = 0
  Vec3T<T> a_t0;  ///< the segment's first end at t = 0
  Vec3T<T> b_t0;  ///< the segment's second end at t = 0
  Vec3T<T> p_t1;  ///< the point at t = 1
  Vec3T<T> a_t1;  ///< the segment's first end at t = 1
  Vec3T<T> b_t1;  ///< the segment's second end at t = 1
};

/// Point-point query: point p against point q, each at t = 0 and t = 1.
/// Member order is the file row order: p_t0, q_t0, p_t1, q_t1.
template <class T>
struct PointPointQueryT {
  Vec3T<T> p_t0;  ///< the first point at t = 0
  Vec3T<T> q_t0;  ///< the second point at t = 0
  Vec3T<T> p_t1;  ///< the first point at t = 1
  Vec3T<T> q_t1;  ///< the second point at t = 1
};

/// Edge-edge query in the plane; rows as EdgeEdgeQueryT with two coordinates.
template <class T>
struct EdgeEdge2dQueryT {
  Vec2T<T> a0_t0;  ///< first endpoint of edge a at t = 0
  Vec2T<T> a1_t0;  ///< second endpoint of edge a at t = 0
  Vec2T<T> b0_t0;  ///< first endpoint of edge b at t = 0
  Vec2T<T> b1_t0;  ///< second endpoint of edge b at t = 0
  Vec2T<T> a0_t1;  ///< first endpoint of edge a at t = 1
  Vec2T<T> a1_t1;  ///< second endpoint of edge a at t = 1
  Vec2T<T> b0_t1;  ///< first endpoint of edge b at t = 1
  Vec2T<T> b1_t1;  ///< second endpoint of edge b at t = 1
};

/// Point-edge query in the plane; rows as PointEdgeQueryT with two coordinates.
template <class T>
struct PointEdge2dQueryT {
  Vec2T<T> p_t0;  ///< the point at t = 0
  Vec2T<T> a_t0;  ///< the segment's first end at t = 0
  Vec2T<T> b_t0;  ///< the segment's second end at t = 0
  Vec2T<T> p_t1;  ///< the point at t = 1
  Vec2T<T> a_t1;  ///< the segment's first end at t = 1
  Vec2T<T> b_t1;  ///< the segment's second end at t = 1
};

/// Point-point query in the plane; rows as PointPointQueryT with two coordinates.
template <class T>
struct PointPoint2dQueryT {
  Vec2T<T> p_t0;  ///< the first point at t = 0
  Vec2T<T> q_t0;  ///< the second point at t = 0
  Vec2T<T> p_t1;  ///< the first point at t = 1
  Vec2T<T> q_t1;  ///< the second point at t = 1
};

using PointEdgeQuery = PointEdgeQueryT<double>;
using PointPointQuery = PointPointQueryT<double>;
using EdgeEdge2dQuery = EdgeEdge2dQueryT<double>;
using PointEdge2dQuery = PointEdge2dQueryT<double>;
using PointPoint2dQuery = PointPoint2dQueryT<double>;

/// The points of a query in file row order (every point at t0, then every point at t1).
template <class T>
std::array<Vec3T<T>, 6> rows(const PointEdgeQueryT<T>& q) {
  return {q.p_t0, q.a_t0, q.b_t0, q.p_t1, q.a_t1, q.b_t1};
}
template <class T>
std::array<Vec3T<T>, 4> rows(const PointPointQueryT<T>& q) {
  return {q.p_t0, q.q_t0, q.p_t1, q.q_t1};
}
template <class T>
std::array<Vec2T<T>, 8> rows(const EdgeEdge2dQueryT<T>& q) {
  return {q.a0_t0, q.a1_t0, q.b0_t0, q.b1_t0, q.a0_t1, q.a1_t1, q.b0_t1, q.b1_t1};
}
template <class T>
std::array<Vec2T<T>, 6> rows(const PointEdge2dQueryT<T>& q) {
  return {q.p_t0, q.a_t0, q.b_t0, q.p_t1, q.a_t1, q.b_t1};
}
template <class T>
std::array<Vec2T<T>, 4> rows(const PointPoint2dQueryT<T>& q) {
  return {q.p_t0, q.q_t0, q.p_t1, q.q_t1};
}

/// The coordinate type of a query type (double, mpq_class, ...): that of its rows. A query type
/// without rows() (the rigid queries of rigid.hpp) specialises QueryCoordinate.
template <class Query, class = void>
struct QueryCoordinate {};
/// The coordinate type of a query type with rows().
template <class Query>
struct QueryCoordinate<Query, std::void_t<decltype(rows(std::declval<const Query&>()))>> {
  using type = std::decay_t<decltype(rows(std::declval<const Query&>())[0].x)>;  ///< that of its rows
};
/// The coordinate type of a query type.
template <class Query>
using coordinate_t = typename QueryCoordinate<Query>::type;

/// Builds a query from its points in file row order.
template <class Query, class Point, std::size_t N>
Query from_rows(const std::array<Point, N>& r) {
  return std::apply([](const auto&... p) { return Query{p...}; }, r);
}

/// The question asked of a query beyond its primitives: do they come within `min_distance`
/// of each other at some time in [0, tmax]? The defaults ask whether they touch during the
/// whole step. Exact semantics: the query collides iff some t in [0, tmax] has
/// dist(A(t), B(t)) <= min_distance (Euclidean distance between the closed primitives), and
/// its time of impact is the earliest such t.
struct CcdParams {
  double min_distance = 0.0;  ///< d: finite, >= 0
  double tmax = 1.0;          ///< the time limit: in (0, 1]

  /// True for the contact question: touching counts (d = 0), no separation asked. The one
  /// place the library asks it (valid parameters have d >= 0, so this is d == 0).
  constexpr bool contact_only() const { return !(min_distance > 0); }
  /// True when the whole step is asked (tmax = 1), not a part [0, tmax] of it.
  constexpr bool whole_step() const { return tmax == 1.0; }
  /// True for the question of the benchmark files' truth column and of exactccd_ccd without
  /// parameters: contact over the whole step.
  constexpr bool contact_over_whole_step() const { return contact_only() && whole_step(); }
};

/// A certified enclosure [lo, hi] of an exact time in [0, 1]: lo <= t <= hi. The library
/// returns the tightest such pair of doubles: lo == hi when t is itself a double, otherwise
/// hi is the double right after lo.
struct TimeInterval {
  double lo = 0.0;  ///< lower bound: lo <= t
  double hi = 0.0;  ///< upper bound: t <= hi
};

/// Equality of both bounds.
inline bool operator==(const TimeInterval& a, const TimeInterval& b) {
  return a.lo == b.lo && a.hi == b.hi;
}

/// How a query is answered. Both methods return the exact answer; they differ in speed.
/// (The non-robust textbook baselines the project compares against are not part of the
/// library: they live in its tools, tools/lib/baseline/ and tools::Method.)
enum class Method {
  filtered,  ///< certified floating-point filters, exact fallback (exact; the default)
  exact,     ///< exact rational arithmetic and CGAL's algebraic kernel (slow reference)
};

}  // namespace exactccd
