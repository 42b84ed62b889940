// What every query function of the C API does (exactccd/exactccd.h), for both motion models
// (c_api.cpp: the linear kinds; rigid_c_api.cpp: rigid bodies): the checks in the order of the
// statuses the header lists, then the C++ entry point (answer_query), whose answer is written to
// the outputs. No exception crosses the boundary; outputs are written only on EXACTCCD_OK.
#pragma once

#include <cmath>
#include <exception>
#include <optional>

#include "exactccd/ccd.hpp"
#include "exactccd/exactccd.h"
#include "numeric/fp_environment.hpp"

namespace exactccd::api {

/// The C call of a query function: EXACTCCD_ERROR_NULL for a null query or output, then the
/// default floating-point environment for the rest of the call (first: DAZ would read -2^-1074
/// as -0), EXACTCCD_ERROR_PARAMETER for a d that is negative or not finite or a tmax outside
/// (0, 1], then `read_and_answer(params)`, the motion model's reading of the query and its
/// answer (a status).
template <class ReadAndAnswer>
exactccd_status c_query_call(const double* query, const int* collides, double d, double tmax,
                             ReadAndAnswer&& read_and_answer) {
  if (!query || !collides) return EXACTCCD_ERROR_NULL;
  const numeric::DefaultFpEnvironment fp_environment;
  if (!(std::isfinite(d) && d >= 0 && tmax > 0 && tmax <= 1)) return EXACTCCD_ERROR_PARAMETER;
  return read_and_answer(CcdParams{d, tmax});
}

/// The answer of a valid query q (read and checked by the caller) to `params` by the filtered
/// method, written to *collides (0 or 1) and, on a collision, to *lo and *hi when not null (the
/// TOI when want_toi); EXACTCCD_ERROR_INTERNAL on an exception.
template <class Query>
exactccd_status write_answer(const Query& q, const CcdParams& params, bool want_toi, int* collides, double* lo,
                             double* hi) {
  try {
    const std::optional<TimeInterval> t = answer_query(q, params, Method::filtered, want_toi, nullptr);
    *collides = t ? 1 : 0;
    if (t && lo) *lo = t->lo;
    if (t && hi) *hi = t->hi;
    return EXACTCCD_OK;
  } catch (const std::exception&) {
    return EXACTCCD_ERROR_INTERNAL;
  }
}

}  // namespace exactccd::api
