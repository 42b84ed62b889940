// Every method the project's tools run (the tools library, not installed): the library's two
// exact methods (exactccd::Method, answered through the public entry points) and the
// non-robust baselines of tools/lib/baseline/ (the textbook method in doubles, with a Bridson-style
// tolerance, and in MPFR at 24, 53, 113 and 256 bits), which the installed library does not
// contain. The CLI (--method, --methods), the benchmarks, the tests, the fuzzers and the
// example plug-ins name a method by tools::Method.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "baseline/naive_ccd.hpp"
#include "exactccd/ccd.hpp"
#include "numeric/fp_environment.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd::tools {

/// How a query is answered. `filtered` and `exact` are the library's (exactccd::Method) and
/// return the exact answer; the others are baselines for comparison, NOT robust: wrong near
/// degeneracies, and their "TOI" is an uncertified double [t, t].
enum class Method {
  filtered,         ///< exactccd::Method::filtered (exact; the default)
  exact,            ///< exactccd::Method::exact (the slow reference)
  naive,            ///< the textbook double-precision cubic
  naive_tolerance,  ///< the textbook method with a Bridson-style tolerance (conservative)
  naive_mpfr24,     ///< the textbook method in MPFR at 24 bits (the precision ladder)
  naive_mpfr53,     ///< ... at 53 bits
  naive_mpfr113,    ///< ... at 113 bits
  naive_mpfr256,    ///< ... at 256 bits
};

/// True for the methods that always return the exact answer (the library's).
constexpr bool is_exact_method(Method m) { return m == Method::filtered || m == Method::exact; }

/// The library's method of an exact method (precondition: is_exact_method(m)).
constexpr exactccd::Method library_method(Method m) {
  return m == Method::exact ? exactccd::Method::exact : exactccd::Method::filtered;
}

/// The tools' name of a library method.
constexpr Method tools_method(exactccd::Method m) {
  return m == exactccd::Method::exact ? Method::exact : Method::filtered;
}

/// The textbook variant of a baseline method (precondition: !is_exact_method(m)).
constexpr baseline::NaiveVariant naive_variant(Method m) {
  switch (m) {
    case Method::naive_tolerance: return baseline::NaiveVariant::tolerance;
    case Method::naive_mpfr24: return baseline::NaiveVariant::mpfr24;
    case Method::naive_mpfr53: return baseline::NaiveVariant::mpfr53;
    case Method::naive_mpfr113: return baseline::NaiveVariant::mpfr113;
    case Method::naive_mpfr256: return baseline::NaiveVariant::mpfr256;
    default: return baseline::NaiveVariant::plain;
  }
}

/// One query by a baseline, with the public entry points' conditions: in the IEEE default
/// floating-point environment whatever the caller's thread has set, and
/// std::invalid_argument (naming the kind's public function, as the library does) on a
/// non-finite coordinate. The TOI is the root found, as [t, t] (uncertified).
template <class Query>
std::optional<TimeInterval> baseline_answer(const Query& q, Method method, bool want_toi) {
  const numeric::DefaultFpEnvironment fp_environment;
  for (const Vec3& v : rows(q))
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::invalid_argument("exactccd::" + std::string(kinds::kind_of<Query>::function) +
                                  (want_toi ? "_toi" : "_ccd") +
                                  ": non-finite coordinate (NaN or infinity) in the query");
  const std::optional<double> t = baseline::naive_toi(q, naive_variant(method));
  if (!t) return std::nullopt;
  return TimeInterval{*t, *t};
}

/// True iff the query collides by `method` (the library's answer for an exact method).
template <class Query>
bool ccd(const Query& q, Method method) {
  if (is_exact_method(method)) return exactccd::ccd(q, library_method(method));
  return baseline_answer(q, method, false).has_value();
}

/// As above; `counters` counts which stage of the filtered method decided (baselines: none).
template <class Query>
bool ccd(const Query& q, Method method, StageCounters& counters) {
  if (is_exact_method(method)) return exactccd::ccd(q, library_method(method), counters);
  return baseline_answer(q, method, false).has_value();
}

/// The time of impact by `method` (certified for the exact methods only).
template <class Query>
std::optional<TimeInterval> toi(const Query& q, Method method) {
  if (is_exact_method(method)) return exactccd::toi(q, library_method(method));
  return baseline_answer(q, method, true);
}

/// As above, with statistics.
template <class Query>
std::optional<TimeInterval> toi(const Query& q, Method method, StageCounters& counters) {
  if (is_exact_method(method)) return exactccd::toi(q, library_method(method), counters);
  return baseline_answer(q, method, true);
}

}  // namespace exactccd::tools
