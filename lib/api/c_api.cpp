// The C API (exactccd/exactccd.h) over the C++ one. No exception crosses the boundary.
#include "exactccd/exactccd.h"

#include <array>
#include <cmath>
#include <exception>
#include <optional>

#include "exactccd/ccd.hpp"
#include "filter/fp_environment.hpp"

namespace {

using namespace exactccd;

template <class Query>
std::optional<Query> read_query(const double* q) {
  std::array<Vec3, 8> rows;
  for (int i = 0; i < 8; ++i) {
    rows[i] = {q[3 * i], q[3 * i + 1], q[3 * i + 2]};
    if (!std::isfinite(q[3 * i]) || !std::isfinite(q[3 * i + 1]) || !std::isfinite(q[3 * i + 2]))
      return std::nullopt;
  }
  return from_rows<Query>(rows);
}

template <class Query, class Toi>
exactccd_status toi_impl(const double* query, int* collides, double* lo, double* hi, Toi&& toi) {
  if (!query || !collides) return EXACTCCD_ERROR_NULL;
  const filter::DefaultFpEnvironment fp_environment;  // as every C++ entry point
  const std::optional<Query> q = read_query<Query>(query);
  if (!q) return EXACTCCD_ERROR_NON_FINITE;
  try {
    const std::optional<TimeInterval> t = toi(*q);
    *collides = t.has_value() ? 1 : 0;
    if (t && lo) *lo = t->lo;
    if (t && hi) *hi = t->hi;
    return EXACTCCD_OK;
  } catch (const std::exception&) {
    return EXACTCCD_ERROR_INTERNAL;
  }
}

}  // namespace

extern "C" {

exactccd_status exactccd_vertex_face_ccd(const double query[24], int* collides) {
  return toi_impl<VertexFaceQuery>(query, collides, nullptr, nullptr, [](const VertexFaceQuery& q) {
    return vertex_face_ccd(q) ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt;
  });
}

exactccd_status exactccd_edge_edge_ccd(const double query[24], int* collides) {
  return toi_impl<EdgeEdgeQuery>(query, collides, nullptr, nullptr, [](const EdgeEdgeQuery& q) {
    return edge_edge_ccd(q) ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt;
  });
}

exactccd_status exactccd_vertex_face_toi(const double query[24], int* collides, double* lo,
                                         double* hi) {
  return toi_impl<VertexFaceQuery>(query, collides, lo, hi,
                                   [](const VertexFaceQuery& q) { return vertex_face_toi(q); });
}

exactccd_status exactccd_edge_edge_toi(const double query[24], int* collides, double* lo,
                                       double* hi) {
  return toi_impl<EdgeEdgeQuery>(query, collides, lo, hi,
                                 [](const EdgeEdgeQuery& q) { return edge_edge_toi(q); });
}

const char* exactccd_status_string(exactccd_status status) {
  switch (status) {
    case EXACTCCD_OK: return "ok";
    case EXACTCCD_ERROR_NON_FINITE: return "non-finite coordinate (NaN or infinity)";
    case EXACTCCD_ERROR_NULL: return "null pointer argument";
    case EXACTCCD_ERROR_INTERNAL: return "internal error";
  }
  return "unknown status";
}

}  // extern "C"
