// Exact conversion of double queries to rational ones (every finite double is a dyadic
// rational, which mpq_class holds exactly).
#pragma once

#include <array>
#include <cstddef>

#include "exactccd/rational.hpp"
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

}  // namespace exactccd::exact
