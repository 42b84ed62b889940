// The public entry points: input validation and dispatch to a method.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "exact/exact_ccd.hpp"

namespace exactccd {
namespace {

/// Every double is a dyadic rational; mpq_class holds it exactly.
RationalVec3 to_rational(const Vec3& v) { return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)}; }

template <class Query>
void require_finite(const Query& q, const char* function) {
  for (const Vec3& v : rows(q))
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::invalid_argument(std::string("exactccd::") + function +
                                  ": non-finite coordinate (NaN or infinity) in the query");
}

template <class RationalQuery, class Query>
RationalQuery to_rational(const Query& q) {
  std::array<RationalVec3, 8> r;
  const auto d = rows(q);
  for (std::size_t i = 0; i < d.size(); ++i) r[i] = to_rational(d[i]);
  return from_rows<RationalQuery>(r);
}

}  // namespace

bool vertex_face_ccd(const VertexFaceQuery& q, Method method) {
  require_finite(q, "vertex_face_ccd");
  switch (method) {
    case Method::exact:
      break;
  }
  return exact::vertex_face_ccd(to_rational<RationalVertexFaceQuery>(q));
}

bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method) {
  require_finite(q, "edge_edge_ccd");
  switch (method) {
    case Method::exact:
      break;
  }
  return exact::edge_edge_ccd(to_rational<RationalEdgeEdgeQuery>(q));
}

bool vertex_face_ccd(const RationalVertexFaceQuery& q) { return exact::vertex_face_ccd(q); }

bool edge_edge_ccd(const RationalEdgeEdgeQuery& q) { return exact::edge_edge_ccd(q); }

std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method) {
  require_finite(q, "vertex_face_toi");
  switch (method) {
    case Method::exact:
      break;
  }
  return exact::vertex_face_toi(to_rational<RationalVertexFaceQuery>(q));
}

std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method) {
  require_finite(q, "edge_edge_toi");
  switch (method) {
    case Method::exact:
      break;
  }
  return exact::edge_edge_toi(to_rational<RationalEdgeEdgeQuery>(q));
}

std::optional<TimeInterval> vertex_face_toi(const RationalVertexFaceQuery& q) {
  return exact::vertex_face_toi(q);
}

std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q) {
  return exact::edge_edge_toi(q);
}

}  // namespace exactccd
