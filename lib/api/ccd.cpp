// The public entry points: input validation and dispatch to a method.
#include "exactccd/ccd.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "baseline/naive_ccd.hpp"
#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "filter/filtered_ccd.hpp"
#include "filter/fp_environment.hpp"

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

// The per-kind entry points of each method, as overload sets, so that one template answers
// both kinds.
bool exact_ccd(const VertexFaceQuery& q) { return exact::vertex_face_ccd(exact::to_rational(q)); }
bool exact_ccd(const EdgeEdgeQuery& q) { return exact::edge_edge_ccd(exact::to_rational(q)); }
std::optional<TimeInterval> exact_toi(const VertexFaceQuery& q) {
  return exact::vertex_face_toi(exact::to_rational(q));
}
std::optional<TimeInterval> exact_toi(const EdgeEdgeQuery& q) {
  return exact::edge_edge_toi(exact::to_rational(q));
}
std::optional<double> naive_toi(const VertexFaceQuery& q, baseline::NaiveVariant v) {
  return baseline::naive_vertex_face_toi(q, v);
}
std::optional<double> naive_toi(const EdgeEdgeQuery& q, baseline::NaiveVariant v) {
  return baseline::naive_edge_edge_toi(q, v);
}
bool filtered_ccd(const VertexFaceQuery& q, StageCounters* c) { return filter::vertex_face_ccd(q, c); }
bool filtered_ccd(const EdgeEdgeQuery& q, StageCounters* c) { return filter::edge_edge_ccd(q, c); }
std::optional<TimeInterval> filtered_toi(const VertexFaceQuery& q, StageCounters* c) {
  return filter::vertex_face_toi(q, c);
}
std::optional<TimeInterval> filtered_toi(const EdgeEdgeQuery& q, StageCounters* c) {
  return filter::edge_edge_toi(q, c);
}
const char* function_name(const VertexFaceQuery&, bool want_toi) {
  return want_toi ? "vertex_face_toi" : "vertex_face_ccd";
}
const char* function_name(const EdgeEdgeQuery&, bool want_toi) {
  return want_toi ? "edge_edge_toi" : "edge_edge_ccd";
}

/// A collision without a TOI (for the boolean functions, only its presence matters).
std::optional<TimeInterval> collides(bool c) { return c ? std::optional(TimeInterval{}) : std::nullopt; }

/// One query by one method: the TOI when want_toi, else a placeholder interval on collision.
template <class Query>
std::optional<TimeInterval> answer(const Query& q, Method method, bool want_toi, StageCounters* counters) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  require_finite(q, function_name(q, want_toi));
  switch (method) {
    case Method::filtered:
      return want_toi ? filtered_toi(q, counters) : collides(filtered_ccd(q, counters));
    case Method::exact:
      return want_toi ? exact_toi(q) : collides(exact_ccd(q));
    default:
      return point_interval(naive_toi(q, naive_variant(method)));
  }
}

}  // namespace

bool vertex_face_ccd(const VertexFaceQuery& q, Method method) {
  return answer(q, method, false, nullptr).has_value();
}
bool vertex_face_ccd(const VertexFaceQuery& q, Method method, StageCounters& counters) {
  return answer(q, method, false, &counters).has_value();
}
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method) {
  return answer(q, method, false, nullptr).has_value();
}
bool edge_edge_ccd(const EdgeEdgeQuery& q, Method method, StageCounters& counters) {
  return answer(q, method, false, &counters).has_value();
}

bool vertex_face_ccd(const RationalVertexFaceQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;  // CGAL's kernel filters with intervals
  return exact::vertex_face_ccd(q);
}
bool edge_edge_ccd(const RationalEdgeEdgeQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;
  return exact::edge_edge_ccd(q);
}

std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method) {
  return answer(q, method, true, nullptr);
}
std::optional<TimeInterval> vertex_face_toi(const VertexFaceQuery& q, Method method,
                                            StageCounters& counters) {
  return answer(q, method, true, &counters);
}
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method) {
  return answer(q, method, true, nullptr);
}
std::optional<TimeInterval> edge_edge_toi(const EdgeEdgeQuery& q, Method method,
                                          StageCounters& counters) {
  return answer(q, method, true, &counters);
}

std::optional<TimeInterval> vertex_face_toi(const RationalVertexFaceQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;
  return exact::vertex_face_toi(q);
}
std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;
  return exact::edge_edge_toi(q);
}

}  // namespace exactccd
