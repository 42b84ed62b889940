// Exact conversion of double queries to rational ones, for both motion models (every finite
// double is a dyadic rational, which mpq_class holds exactly).
#pragma once

#include <array>
#include <cstddef>

#include "exactccd/rational.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

inline RationalVec3 to_rational(const Vec3& v) {
  return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)};
}

inline Vec2T<mpq_class> to_rational(const Vec2& v) { return {mpq_class(v.x), mpq_class(v.y)}; }

/// The query of any kind with the same (exact) coordinates in rationals.
template <template <class> class QueryT>
QueryT<mpq_class> to_rational(const QueryT<double>& q) {
  const auto d = rows(q);
  std::array<decltype(to_rational(d[0])), d.size()> r;
  for (std::size_t i = 0; i < d.size(); ++i) r[i] = to_rational(d[i]);
  return from_rows<QueryT<mpq_class>>(r);
}

/// A rigid pose with the same (exact) components in rationals.
inline RigidPoseT<mpq_class> to_rational(const RigidPose& p) {
  return {to_rational(p.c), {mpq_class(p.q.w), mpq_class(p.q.x), mpq_class(p.q.y), mpq_class(p.q.z)}};
}

/// The rigid vertex-face query with the same (exact) numbers in rationals.
inline RigidVertexFaceQueryT<mpq_class> to_rational(const RigidVertexFaceQuery& q) {
  return {to_rational(q.a_t0), to_rational(q.a_t1), to_rational(q.b_t0), to_rational(q.b_t1),
          to_rational(q.p),    to_rational(q.a),    to_rational(q.b),    to_rational(q.c)};
}

/// The rigid edge-edge query with the same (exact) numbers in rationals.
inline RigidEdgeEdgeQueryT<mpq_class> to_rational(const RigidEdgeEdgeQuery& q) {
  return {to_rational(q.a_t0), to_rational(q.a_t1), to_rational(q.b_t0), to_rational(q.b_t1),
          to_rational(q.a0),   to_rational(q.a1),   to_rational(q.b0),   to_rational(q.b1)};
}

}  // namespace exactccd::exact
