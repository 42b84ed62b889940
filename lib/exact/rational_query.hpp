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

inline RationalVertexFaceQuery to_rational(const VertexFaceQuery& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < d.size(); ++i) r[i] = to_rational(d[i]);
  return from_rows<RationalVertexFaceQuery>(r);
}

inline RationalEdgeEdgeQuery to_rational(const EdgeEdgeQuery& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < d.size(); ++i) r[i] = to_rational(d[i]);
  return from_rows<RationalEdgeEdgeQuery>(r);
}

}  // namespace exactccd::exact
