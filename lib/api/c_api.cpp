// The C API (exactccd/exactccd.h) of the linear kinds over the C++ one, by the one pattern of
// every C query function (c_query.hpp; rigid bodies: rigid_c_api.cpp). No exception crosses the
// boundary.
#include "exactccd/exactccd.h"

#include <cmath>
#include <cstddef>
#include <exception>
#include <optional>
#include <vector>

#include "api/c_query.hpp"
#include "exactccd/ccd.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/fp_environment.hpp"

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

/// The C API's query of any kind (exactccd_kind value `kind`, its doubles in `query`): the calls
/// of exactccd_ccd, exactccd_toi and the named functions (api/c_query.hpp).
exactccd_status answer_c_query(int kind, const double* query, double d, double tmax, bool want_toi, int* collides,
                               double* lo, double* hi) {
  return api::c_query_call(query, collides, d, tmax, [&](const CcdParams& params) {
    exactccd_status status = EXACTCCD_ERROR_PARAMETER;  // an unknown kind
    visit_c_kind(kind, [&](auto k) {
      using Query = typename decltype(k)::template Query<double>;
      const std::optional<Query> q = read_any_query<Query>(query);
      status = q ? api::write_answer(*q, params, want_toi, collides, lo, hi) : EXACTCCD_ERROR_NON_FINITE;
    });
    return status;
  });
}

/// exactccd_toi_batch for queries of type Query (after the calls' checks): every query read and
/// checked, then answered at once (answer_batch), then written.
template <class Query>
exactccd_status answer_c_batch(const double* queries, std::size_t count, const CcdParams& params, int* collides,
                               double* lo, double* hi) {
  using Kind = kinds::kind_of<Query>;
  constexpr std::size_t size = 2 * Kind::points * Kind::dimension;
  try {
    std::vector<Query> read(count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::optional<Query> q = read_any_query<Query>(queries + i * size);
      if (!q) return EXACTCCD_ERROR_NON_FINITE;
      read[i] = *q;
    }
    std::vector<std::optional<TimeInterval>> answers(count);
    answer_batch(read.data(), count, params, Method::filtered, lo != nullptr, answers.data());
    for (std::size_t i = 0; i < count; ++i) {
      collides[i] = answers[i] ? 1 : 0;
      if (answers[i] && lo) lo[i] = answers[i]->lo;
      if (answers[i] && hi) hi[i] = answers[i]->hi;
    }
    return EXACTCCD_OK;
  } catch (const std::exception&) {
    return EXACTCCD_ERROR_INTERNAL;
  }
}

}  // namespace

extern "C" {

exactccd_status exactccd_toi_batch(int kind, const double* queries, size_t count, double min_distance, double tmax,
                                   int* collides, double* lo, double* hi) {
  if ((count > 0 && (!queries || !collides)) || (lo == nullptr) != (hi == nullptr)) return EXACTCCD_ERROR_NULL;
  const numeric::DefaultFpEnvironment fp_environment;  // first: DAZ would read -2^-1074 as -0
  if (!(std::isfinite(min_distance) && min_distance >= 0 && tmax > 0 && tmax <= 1)) return EXACTCCD_ERROR_PARAMETER;
  exactccd_status status = EXACTCCD_ERROR_PARAMETER;  // an unknown kind
  visit_c_kind(kind, [&](auto k) {
    using Query = typename decltype(k)::template Query<double>;
    status = answer_c_batch<Query>(queries, count, CcdParams{min_distance, tmax}, collides, lo, hi);
  });
  return status;
}

int exactccd_query_size(int kind) {
  int size = 0;
  visit_c_kind(kind, [&](auto k) { size = 2 * decltype(k)::points * decltype(k)::dimension; });
  return size;
}

exactccd_status exactccd_ccd(int kind, const double* query, double min_distance, double tmax, int* collides) {
  return answer_c_query(kind, query, min_distance, tmax, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_toi(int kind, const double* query, double min_distance, double tmax, int* collides,
                             double* lo, double* hi) {
  return answer_c_query(kind, query, min_distance, tmax, true, collides, lo, hi);
}

exactccd_status exactccd_vertex_face_ccd(const double query[24], int* collides) {
  return answer_c_query(EXACTCCD_VERTEX_FACE, query, 0, 1, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_edge_edge_ccd(const double query[24], int* collides) {
  return answer_c_query(EXACTCCD_EDGE_EDGE, query, 0, 1, false, collides, nullptr, nullptr);
}

exactccd_status exactccd_vertex_face_toi(const double query[24], int* collides, double* lo,
                                         double* hi) {
  return answer_c_query(EXACTCCD_VERTEX_FACE, query, 0, 1, true, collides, lo, hi);
}

exactccd_status exactccd_edge_edge_toi(const double query[24], int* collides, double* lo,
                                       double* hi) {
  return answer_c_query(EXACTCCD_EDGE_EDGE, query, 0, 1, true, collides, lo, hi);
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
