// The C API (exactccd/exactccd.h) over the C++ one. No exception crosses the boundary.
#include "exactccd/exactccd.h"

#include <array>
#include <cmath>
#include <exception>
#include <optional>

#include "exactccd/ccd.hpp"
#include "numeric/fp_environment.hpp"
#include "kinds/primitive_kinds.hpp"

namespace {

using namespace exactccd;


/// The query of a kind from its doubles (query_size of them), or nullopt on a non-finite one.
template <class Query>
std::optional<Query> read_any_query(const double* q) {
  using Kind = kinds::kind_of<Query>;
  auto r = rows(Query{});
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double* c = q + Kind::dimension * i;
    for (int k = 0; k < Kind::dimension; ++k)
      if (!std::isfinite(c[k])) return std::nullopt;
    r[i].x = c[0];
    r[i].y = c[1];
    if constexpr (Kind::dimension == 3) r[i].z = c[2];
  }
  return from_rows<Query>(r);
}

template <class Query, class Toi>
exactccd_status toi_impl(const double* query, int* collides, double* lo, double* hi, Toi&& toi) {
  if (!query || !collides) return EXACTCCD_ERROR_NULL;
  const numeric::DefaultFpEnvironment fp_environment;  // as every C++ entry point
  const std::optional<Query> q = read_any_query<Query>(query);
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


/// Calls f(Kind{}) for the kind whose exactccd_kind value is `kind` (Kind::c_kind); false for an
/// unknown value.
template <class F>
bool visit_c_kind(int kind, F&& f) {
  bool found = false;
  kinds::for_each_kind([&](auto k) {
    if (decltype(k)::c_kind == kind) {
      f(k);
      found = true;
    }
  });
  return found;
}

exactccd_status separation_impl(int kind, const double* query, double d, double tmax, bool want_toi,
                                int* collides, double* lo, double* hi) {
  if (!query || !collides) return EXACTCCD_ERROR_NULL;
  const numeric::DefaultFpEnvironment fp_environment;  // first: DAZ would read -2^-1074 as -0
  if (!(std::isfinite(d) && d >= 0 && tmax > 0 && tmax <= 1)) return EXACTCCD_ERROR_PARAMETER;
  exactccd_status status = EXACTCCD_ERROR_PARAMETER;
  visit_c_kind(kind, [&](auto k) {
    using Query = typename decltype(k)::template Query<double>;
    const std::optional<Query> q = read_any_query<Query>(query);
    if (!q) {
      status = EXACTCCD_ERROR_NON_FINITE;
      return;
    }
    try {
      const CcdParams params{d, tmax};
      const std::optional<TimeInterval> t =
          want_toi ? toi(*q, params) : (ccd(*q, params) ? std::optional(TimeInterval{}) : std::nullopt);
      *collides = t.has_value() ? 1 : 0;
      if (t && lo) *lo = t->lo;
      if (t && hi) *hi = t->hi;
      status = EXACTCCD_OK;
    } catch (const std::exception&) {
      status = EXACTCCD_ERROR_INTERNAL;
    }
  });
  return status;
}

}  // namespace

extern "C" {

int exactccd_query_size(int kind) {
  int size = 0;
  visit_c_kind(kind, [&](auto k) { size = 2 * decltype(k)::points * decltype(k)::dimension; });
  return size;
}

exactccd_status exactccd_ccd(int kind, const double* query, double min_distance, double tmax, int* collides) {
  return separation_impl(kind, query, min_distance, tmax, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                             double* lo, double* hi) {
  return separation_impl(kind, query, min_distance, tmax, true, collides, lo, hi);
}

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
    case EXACTCCD_ERROR_PARAMETER: return "bad parameter (unknown kind, min_distance < 0 or not finite, tmax not in (0, 1], threads > 1024)";
    case EXACTCCD_ERROR_INDEX: return "a candidate's vertex index is out of range or repeated";
    case EXACTCCD_ERROR_CAPACITY: return "output arrays too small (*count holds the size needed)";
    case EXACTCCD_ERROR_ROTATION: return "a rigid body's quaternion path passes through zero";
  }
  return "unknown status";
}

}  // extern "C"
