// The public entry points: input validation and dispatch to a method.
#include "exactccd/ccd.hpp"
#include "exactccd/rational.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "exact/exact_ccd.hpp"
#include "exact/rational_query.hpp"
#include "filter/filtered_ccd.hpp"
#include "filter/fp_environment.hpp"
#include "kinds/primitive_kinds.hpp"

namespace exactccd {
namespace {

/// Throws std::invalid_argument, naming the public function (from the kind's description), on
/// a non-finite coordinate; the name is built only then (no allocation on the hot path).
template <class Query>
void require_finite(const Query& q, bool want_toi) {
  for (const Vec3& v : rows(q))
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::invalid_argument("exactccd::" + std::string(kinds::kind_of<Query>::function) +
                                  (want_toi ? "_toi" : "_ccd") +
                                  ": non-finite coordinate (NaN or infinity) in the query");
}

/// A collision without a TOI (for the boolean functions, only its presence matters).
std::optional<TimeInterval> collides(bool c) { return c ? std::optional(TimeInterval{}) : std::nullopt; }

/// One query by one method: the TOI when want_toi, else a placeholder interval on collision.
template <class Query>
std::optional<TimeInterval> answer(const Query& q, Method method, bool want_toi, StageCounters* counters) {
  const filter::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  require_finite(q, want_toi);
  switch (method) {
    case Method::filtered:
      return filter::filtered(q, want_toi, counters);
    case Method::exact:
      return want_toi ? exact::toi(exact::to_rational(q)) : collides(exact::ccd(exact::to_rational(q)));
  }
  throw std::invalid_argument("exactccd::" + std::string(kinds::kind_of<Query>::function) +
                              (want_toi ? "_toi" : "_ccd") + ": unknown method");
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
  return exact::ccd(q);
}
bool edge_edge_ccd(const RationalEdgeEdgeQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;
  return exact::ccd(q);
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
  return exact::toi(q);
}
std::optional<TimeInterval> edge_edge_toi(const RationalEdgeEdgeQuery& q) {
  const filter::DefaultFpEnvironment fp_environment;
  return exact::toi(q);
}

}  // namespace exactccd
