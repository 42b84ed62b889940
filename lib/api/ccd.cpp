// The public entry points: input validation and dispatch to a method.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "baseline/naive_ccd.hpp"
#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "filter/filtered_ccd.hpp"

namespace exactccd {
namespace {

template <class Query>
void require_finite(const Query& q, const char* function) {
  for (const Vec3& v : rows(q))
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::invalid_argument(std::string("exactccd::") + function +
                                  ": non-finite coordinate (NaN or infinity) in the query");
}

std::optional<TimeInterval> point_interval(std::optional<double> t) {
  if (!t) return std::nullopt;
  return TimeInterval{*t, *t};
}

baseline::NaiveVariant naive_variant(Method m) {
  switch (m) {
    case Method::naive_tolerance: return baseline::NaiveVariant::tolerance;
    case Method::naive_mpfr24: return baseline::NaiveVariant::mpfr24;
    case Method::naive_mpfr53: return baseline::NaiveVariant::mpfr53;
    case Method::naive_mpfr113: return baseline::NaiveVariant::mpfr113;
    case Method::naive_mpfr256: return baseline::NaiveVariant::mpfr256;
    default: return baseline::NaiveVariant::plain;
  }
}

std::optional<TimeInterval> toi(const VertexFaceQuery& q, Method method, bool want_toi,
                                StageCounters* counters) {
  require_finite(q, want_toi ? "vertex_face_toi" : "vertex_face_ccd");
  switch (method) {
    case Method::exact:
      if (!want_toi)
        return exact::vertex_face_ccd(exact::to_rational(q)) ? std::optional(TimeInterval{})
                                                             : std::nullopt;
      return exact::vertex_face_toi(exact::to_rational(q));
    case Method::filtered:
      break;
    default:
      return point_interval(baseline::naive_vertex_face_toi(q, naive_variant(method)));
  }
  return want_toi ? filter::vertex_face_toi(q, counters)
                  : (filter::vertex_face_ccd(q, counters) ? std::optional(TimeInterval{})
                                                          : std::nullopt);
}

std::optional<TimeInterval> toi(const EdgeEdgeQuery& q, Method method, bool want_toi,
                                StageCounters* counters) {
  require_finite(q, want_toi ? "edge_edge_toi" : "edge_edge_ccd");
  switch (method) {
    case Method::exact:
      if (!want_toi)
        return exact::edge_edge_ccd(exact::to_rational(q)) ? std::optional(TimeInterval{})
                                                           : std::nullopt;
      return exact::edge_edge_toi(exact::to_rational(q));
    case Method::filtered:
      break;
    default:
      return point_interval(baseline::naive_edge_edge_toi(q, naive_variant(method)));
  }
  return want_toi ? filter::edge_edge_toi(q, counters)
                  : (filter::edge_edge_ccd(q, counters) ? std::optional(TimeInterval{})
                                                        : std::nullopt);
}

}  // namespace

bool vertex_face_ccd(const VertexFaceQuery& q, Method method) {
  return toi(q, method, false, nullptr).has_value();
}
bool vertex_face_ccd(const VertexFaceQuery& q, Method method, StageCounters& counters) {
  return toi(q, method, false, &counters).has_value();
}
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method) {
  return toi(q, method, false, nullptr).has_value();
}
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method, StageCounters& counters) {
  return toi(q, method, false, &counters).has_value();
}

bool vertex_face_ccd(const RationalVertexFaceQuery& q) { return exact::vertex_face_ccd(q); }
bool edge_edge_ccd(const RationalEdgeEdgeQuery& q) { return exact::edge_edge_ccd(q); }

std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method) {
  return toi(q, method, true, nullptr);
}
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method,
                                            StageCounters& counters) {
  return toi(q, method, true, &counters);
}
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method) {
  return toi(q, method, true, nullptr);
}
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method,
                                          StageCounters& counters) {
  return toi(q, method, true, &counters);
}

std::optional<TimeInterval> vertex_face_toi(const RationalVertexFaceQuery& q) {
  return exact::vertex_face_toi(q);
}
std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q) {
  return exact::edge_edge_toi(q);
}

}  // namespace exactccd
